// Graded tests of exercise 13.1 (the refinement oracle). One point per test.
#include <gtest/gtest.h>

#include "gi/radiosity/hierarchical/oracle.hpp"
#include "support/print.hpp"

namespace {
// A link that brings q's light to p: F_pq, F_qp and the visibility.
gi::Link link(double F, double F_back, double visibility = 1) { return gi::Link{0, 1, F, F_back, visibility}; }
const gi::Refinement accept = gi::Refinement::Accept, receiver = gi::Refinement::SplitReceiver,
                     source = gi::Refinement::SplitSource;
}  // namespace

TEST(Ex13_1_Oracle, AcceptsWhatIsBelowTheThreshold) {
  EXPECT_EQ(gi::oracle(link(0.04, 0.01), 1, 0.05, true, true), accept)
      << "error = brightness * max(F_pq, F_qp) = 0.04 <= threshold 0.05: accept the link as it is";
  EXPECT_EQ(gi::oracle(link(0.01, 0.04), 1, 0.05, true, true), accept) << "max(F_pq, F_qp) = 0.04: accept";
  EXPECT_EQ(gi::oracle(link(0.3, 0.2), 0.1, 0.05, true, true), accept)
      << "BF-refinement: brightness 0.1 times max F 0.3 = 0.03 <= 0.05: a dim link may be coarse";
}

TEST(Ex13_1_Oracle, TheLargerFormFactorCountsFromEitherEnd) {
  EXPECT_NE(gi::oracle(link(0.01, 0.2), 1, 0.05, true, true), accept)
      << "F_pq is small but F_qp = 0.2: the error is the larger of the two, 0.2 > 0.05, so refine";
  EXPECT_NE(gi::oracle(link(0.2, 0.01), 1, 0.05, true, true), accept) << "F_pq = 0.2 > 0.05: refine";
}

TEST(Ex13_1_Oracle, SplitsTheEndThatLooksBigger) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.05), 1, 0.1, true, true), source)
      << "F_pq >= F_qp: the source fills more of the receiver's view (A_q >= A_p by reciprocity), split the source";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3), 1, 0.1, true, true), receiver)
      << "F_qp > F_pq: the receiver is the bigger end, split the receiver";
}

TEST(Ex13_1_Oracle, AnEndAtTheMinimumAreaIsNotSplit) {
  EXPECT_EQ(gi::oracle(link(0.3, 0.05), 1, 0.1, true, false), accept)
      << "the source should be split but is at the minimum area: accept the link, do not split the other end";
  EXPECT_EQ(gi::oracle(link(0.05, 0.3), 1, 0.1, false, true), accept)
      << "the receiver should be split but is at the minimum area: accept";
}

TEST(Ex13_1_Oracle, APartlyHiddenLinkIsRefinedFurther) {
  // error 0.04 <= 0.1 when fully visible; a shadow edge inside counts 4 times: 0.16.
  EXPECT_EQ(gi::oracle(link(0.04, 0.01, 1.0), 1, 0.1, true, true), accept) << "fully visible: 0.04 <= 0.1";
  EXPECT_NE(gi::oracle(link(0.04, 0.01, 0.5), 1, 0.1, true, true), accept)
      << "visibility 0.5: a shadow edge lies inside the link; its error counts partial_visibility_factor (4) times";
  EXPECT_EQ(gi::oracle(link(0.04, 0.01, 0.0), 1, 0.1, true, true), accept)
      << "wholly hidden: no shadow edge inside, judge it as a visible one (0.04 <= 0.1)";
}

TEST(Ex13_1_Oracle, AHiddenLinkIsNotAcceptedForBeingHidden) {
  EXPECT_EQ(gi::oracle(link(0.5, 0.1, 0.0), 1, 0.1, true, true), source)
      << "visibility 0 from a few rays does not make the error 0: a big hidden link is split like a visible one";
}
