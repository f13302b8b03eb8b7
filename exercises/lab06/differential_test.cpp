// Graded tests of exercise 6.1: the differential form factor with visibility. One
// point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "support/print.hpp"

using gi::vec3;

namespace {
const double pi = 3.14159265358979323846;
}

namespace {
// Which slip gives f for two points facing each other straight on, r = 2 apart, A_j = 0.5.
std::string facing_slip(double f) {
  const double want = 0.5 / (4 * pi);
  const auto near = [&](double v) { return std::abs(f - v) <= 1e-12 * std::abs(v); };
  const std::string got = " (got F = " + testing::PrintToString(f) + ", want cos_i cos_j / (pi r^2) A_j = 1 * 1 / "
                          "(pi * 4) * 0.5 = " + testing::PrintToString(want) + ")";
  if (f == 0)
    return "the points face each other, both cosines are 1, yet F = 0: with d = x_j - x_i, cos_i = n_i . d / r but "
           "cos_j = -n_j . d / r (the receiver's cosine is measured towards x_i, hence the minus)" + got;
  const double f_unit_area = gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 1.0, 1.0);
  if (near(f_unit_area))
    return "F does not change when the receiver's area A_j goes from 0.5 to 1: multiply by A_j, the form factor "
           "is to the receiver's patch, not to a point" + got;
  if (near(4 * want))
    return "F is 4 times too large, r^2 = 4: the cosines were taken with the raw difference x_j - x_i (length 2); "
           "divide it by r first, so that each cosine is 1" + got;
  if (near(pi * want)) return "F is pi times too large: F = cos_i cos_j / (pi r^2) A_j, did you forget the 1/pi?" + got;
  if (near(2 * want)) return "F is 2 times too large, r = 2: divide by r^2, not by r" + got;
  return "F = cos_i cos_j / (pi r^2) A_j: check the 1/pi and that r is squared" + got;
}
}  // namespace

TEST(Ex6_1_Differential, FacingPointsStraightOn) {
  // Both cosines 1, r = 2, A_j = 0.5: F = 1 * 1 / (pi * 4) * 0.5.
  const double f = gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 0.5, 1.0);
  EXPECT_NEAR(f, 0.5 / (4 * pi), 1e-15) << facing_slip(f);
}

TEST(Ex6_1_Differential, ObliqueUsesBothCosines) {
  // x_j = (1, 0, 1): r^2 = 2; cos_i = cos_j = 1/sqrt(2).
  EXPECT_NEAR(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {-1, 0, 0}, 1.0, 1.0), 0.5 / (2 * pi),
              1e-15)
      << "both cosines count, each with the unit vector between the points";
}

TEST(Ex6_1_Differential, UnitVectorNotTheRawDifference) {
  // r = 3 along z: cos = 1, not 3.
  EXPECT_NEAR(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 3}, {0, 0, -1}, 1.0, 1.0), 1 / (9 * pi),
              1e-15)
      << "normalise the direction before taking the cosines";
}

TEST(Ex6_1_Differential, ReceiverFacingAwayGetsNothing) {
  EXPECT_EQ(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 1.0, 1.0), 0.0)
      << "the receiver's back faces the sender (cos_j < 0): no energy arrives. Do not take |cos|";
}

TEST(Ex6_1_Differential, ReceiverBehindTheSenderGetsNothing) {
  EXPECT_EQ(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, -2}, {0, 0, 1}, 1.0, 1.0), 0.0)
      << "the receiver is behind the sender's surface (cos_i < 0)";
}

TEST(Ex6_1_Differential, VisibilityScales) {
  const double open = gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 1.0, 1.0);
  EXPECT_EQ(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 1.0, 0.0), 0.0)
      << "H_ij = 0: a blocked pair exchanges nothing";
  EXPECT_NEAR(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 1.0, 0.25), 0.25 * open,
              1e-15)
      << "multiply by the visibility H_ij";
}

TEST(Ex6_1_Differential, GoodFarAwayForPatches) {
  // Unit squares 10 apart: centre to centre is within 1% of the exact patch factor.
  const double exact = gi::ff_parallel_rectangles(1, 1, 10);
  EXPECT_NEAR(gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {0, 0, 10}, {0, 0, -1}, 1.0, 1.0), exact,
              0.01 * exact)
      << "two unit squares 10 apart: the centre-to-centre formula is within 1% of the exact patch form factor";
}
