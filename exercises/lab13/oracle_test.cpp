// Graded tests of exercise 13.1 (the refinement oracle). One point per test.
#include <gtest/gtest.h>

#include "gi/radiosity/hierarchical/oracle.hpp"
#include "support/print.hpp"

namespace {
// A link that brings q's light to p: F_pq, F_qp, the least and greatest point F over
// the receiver, and the visibility.
gi::Link link(double F, double F_back, float F_min, float F_max, double visibility = 1) {
  gi::Link l{0, 1, F, F_back, visibility};
  l.F_min = F_min, l.F_max = F_max;
  return l;
}
const gi::Brightness unit{1, 1};
const gi::Refinement accept = gi::Refinement::Accept, receiver = gi::Refinement::SplitReceiver,
                     source = gi::Refinement::SplitSource;
}  // namespace

TEST(Ex13_1_Oracle, AcceptsWhatChangesLittleAcrossTheReceiver) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.1, 0.28f, 0.32f), unit, 0.05, true, true), accept)
      << "error = greatest * F_max - least * F_min = 0.32 - 0.28 = 0.04 <= 0.05: a big F that is the same "
         "everywhere on the receiver is carried exactly; accept";
  EXPECT_EQ(gi::oracle(link(0.3, 0.1, 0.2f, 0.4f), {0.2, 0.2}, 0.05, true, true), accept)
      << "BF-refinement: brightness 0.2 * (0.4 - 0.2) = 0.04 <= 0.05: a dim link may be coarse";
}

TEST(Ex13_1_Oracle, RefinesWhereFChangesEvenIfFIsSmall) {
  EXPECT_NE(gi::oracle(link(0.03, 0.01, 0.0f, 0.09f), unit, 0.05, true, true), accept)
      << "F = 0.03 is small, but it runs from 0 to 0.09 across the receiver: error 0.09 > 0.05, refine "
         "(bounding F itself, Hanrahan et al.'s first oracle, would accept it)";
}

TEST(Ex13_1_Oracle, TheSourcesBrightnessRangeCounts) {
  EXPECT_NE(gi::oracle(link(0.3, 0.1, 0.3f, 0.3f), {0.0, 0.5}, 0.05, true, true), accept)
      << "F is constant, but the source's parts range from dark to 0.5: error 0.5 * 0.3 - 0 * 0.3 = 0.15 > 0.05; "
         "the mean B a link carries is wrong for every point when the source is not uniform";
}

TEST(Ex13_1_Oracle, SplitsTheEndTheErrorLivesIn) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.05, 0.1f, 0.5f), unit, 0.1, true, true), receiver)
      << "F runs from 0.1 to 0.5 across the receiver and the source is uniform: split the receiver. The source "
         "looks bigger (F_pq >= F_qp), but F is exact for a whole source: cutting it only shares the same error "
         "among four links to this receiver";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3, 0.3f, 0.3f), {0.0, 0.5}, 0.1, true, true), source)
      << "F is the same all over the receiver; the error is the source's range, dark to 0.5: split the source, "
         "although the receiver looks bigger";
  EXPECT_EQ(gi::oracle(link(0.3, 0.05, 0.28f, 0.32f, 0.5), unit, 0.1, true, true), source)
      << "a shadow edge inside (V = 0.5): cut the end that looks bigger, here the source (F_pq >= F_qp)";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3, 0.28f, 0.32f, 0.5), unit, 0.1, true, true), receiver)
      << "a shadow edge inside (V = 0.5) and F_qp > F_pq: the receiver is the bigger end, split it";
}

TEST(Ex13_1_Oracle, TiesFollowTheRule) {
  // Values exact in binary, so that each tie is exact.
  EXPECT_EQ(gi::oracle(link(0.3, 0.1, 0.25f, 0.5f), unit, 0.25, true, true), accept)
      << "error = 0.5 - 0.25 = 0.25, exactly the threshold: accept (error <= threshold); refining at equality "
         "cuts every link that just meets the bound";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3, 0.25f, 0.375f), {0.5, 1.0}, 0.1, true, true), receiver)
      << "the error over the receiver, 1 * (0.375 - 0.25) = 0.125, equals the one over the source, "
         "(1 - 0.5) * 0.25 = 0.125: a tie splits the receiver (the source only when its part is larger)";
  EXPECT_EQ(gi::oracle(link(0.2, 0.2, 0.28f, 0.32f, 0.5), unit, 0.1, true, true), source)
      << "a shadow edge inside and F_pq = F_qp: a tie cuts the source (F_pq >= F_qp)";
}

TEST(Ex13_1_Oracle, AnEndAtTheMinimumAreaLeavesTheOther) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.05, 0.1f, 0.5f), unit, 0.1, false, true), source)
      << "the receiver should be split but is at the minimum area: split the source instead";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3, 0.3f, 0.3f), {0.0, 0.5}, 0.1, true, false), receiver)
      << "the source should be split but is at the minimum area: split the receiver instead";
  EXPECT_EQ(gi::oracle(link(0.3, 0.05, 0.1f, 0.5f), unit, 0.1, false, false), accept)
      << "neither end can be split: accept the link as it is";
}

TEST(Ex13_1_Oracle, APartlyHiddenLinkIsRefinedFurther) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.1, 0.28f, 0.32f, 1.0), unit, 0.05, true, true), accept)
      << "fully visible: 0.32 - 0.28 = 0.04 <= 0.05";
  EXPECT_NE(gi::oracle(link(0.3, 0.1, 0.28f, 0.32f, 0.5), unit, 0.05, true, true), accept)
      << "visibility 0.5: a shadow edge lies inside the link, where the light falls to nothing; F_min counts "
         "as 0, so the error is 0.32 > 0.05";
  EXPECT_EQ(gi::oracle(link(0.3, 0.1, 0.28f, 0.32f, 0.0), unit, 0.05, true, true), accept)
      << "wholly hidden: no shadow edge inside, judge it as a visible one (0.04 <= 0.05)";
  EXPECT_NE(gi::oracle(link(0.3, 0.1, 0.0f, 0.5f, 0.0), unit, 0.05, true, true), accept)
      << "wholly hidden to a few rays is not accurate: F runs from 0 to 0.5 across the receiver, error 0.5 > 0.05, "
         "refine it as a visible link";
}
