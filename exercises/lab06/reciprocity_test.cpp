// Graded tests of exercise 6.3: the reciprocity check. One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/radiosity/system/form_factor_matrix.hpp"
#include "support/print.hpp"

namespace {
gi::FormFactorMatrix matrix(int n, std::vector<double> values) { return {n, std::move(values)}; }
}  // namespace

TEST(Ex6_3_Reciprocity, ConsistentMatrixScoresZero) {
  // A_0 F_01 = 1 * 0.4 = A_1 F_10 = 2 * 0.2.
  EXPECT_NEAR(gi::reciprocity_error(matrix(2, {0, 0.4, 0.2, 0}), {1, 2}), 0.0, 1e-15)
      << "F_01 differs from F_10, but A_0 F_01 = A_1 F_10: reciprocity holds (weight each F by its own row's area)";
}

TEST(Ex6_3_Reciprocity, ViolationIsRelativeToTheLargerSide) {
  // A_0 F_01 = 0.4, A_1 F_10 = 0.6: |0.4 - 0.6| / 0.6.
  EXPECT_NEAR(gi::reciprocity_error(matrix(2, {0, 0.4, 0.3, 0}), {1, 2}), 1.0 / 3, 1e-12)
      << "|A_0 F_01 - A_1 F_10| / max(A_0 F_01, A_1 F_10) = |0.4 - 0.6| / 0.6";
}

TEST(Ex6_3_Reciprocity, EitherSideMayBeLarger) {
  EXPECT_NEAR(gi::reciprocity_error(matrix(2, {0, 0.8, 0.2, 0}), {1, 2}), 0.5, 1e-12)
      << "A_0 F_01 = 0.8 > A_1 F_10 = 0.4: take the absolute difference";
}

TEST(Ex6_3_Reciprocity, TheWorstPairCounts) {
  // Three elements of area 1: pair (0,1) is off by 0.1 / 0.5, the others agree. Then
  // the same with the bad pair last.
  const gi::FormFactorMatrix first = matrix(3, {0, 0.5, 0.2,  //
                                                0.4, 0, 0.3,  //
                                                0.2, 0.3, 0});
  EXPECT_NEAR(gi::reciprocity_error(first, {1, 1, 1}), 0.2, 1e-12)
      << "the worst pair is (0, 1), checked first: keep the largest violation over all pairs, not the last one";
  const gi::FormFactorMatrix last = matrix(3, {0, 0.3, 0.2,  //
                                               0.3, 0, 0.5,  //
                                               0.2, 0.4, 0});
  EXPECT_NEAR(gi::reciprocity_error(last, {1, 1, 1}), 0.2, 1e-12) << "check every pair i, j, keep the largest";
}

TEST(Ex6_3_Reciprocity, PairsThatSeeNothingAreSkipped) {
  const double e = gi::reciprocity_error(matrix(3, {0, 0, 0.5, 0, 0, 0, 0.5, 0, 0}), {1, 1, 1});
  EXPECT_FALSE(std::isnan(e)) << "0/0 for pairs with F = 0 both ways: skip pairs below the floor";
  EXPECT_NEAR(e, 0.0, 1e-15) << "the only pair that sees anything, (0, 2), is reciprocal";
}

TEST(Ex6_3_Reciprocity, OneWayExchangeIsTheWorstViolation) {
  // Element 0 sees element 1, which does not see it back: |0.5 - 0| / 0.5 = 1.
  EXPECT_NEAR(gi::reciprocity_error(matrix(2, {0, 0.5, 0, 0}), {1, 1}), 1.0, 1e-12)
      << "F_01 = 0.5 but F_10 = 0: a violation of 1. Skip a pair only when both sides are below the floor";
}
