// Graded tests of exercises 7.1 and 7.2: the delta form factors of hemicube cells.
// One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>

#include "gi/radiosity/form_factors/hemicube.hpp"
#include "support/print.hpp"

namespace {
const double pi = 3.14159265358979323846;
const double dA = 0.0004;  // a 0.02 x 0.02 cell
// Form factor from a point to the whole top face, [-1, 1]^2 at height 1: four corner
// rectangles of Howell's case, 4 * (1 / 2pi) * 2 * atan(1 / sqrt 2) / sqrt 2.
const double top_share = 4.0 / pi * std::atan(1 / std::sqrt(2.0)) / std::sqrt(2.0);
}  // namespace

TEST(Ex7_1_DeltaTop, CentreCellIsAreaOverPi) {
  const double f = gi::delta_form_factor_top(0, 0, dA);
  const std::string got = " (got " + testing::PrintToString(f) + ", want dA / pi = " + testing::PrintToString(dA / pi) +
                          " for a cell of area dA = 0.0004)";
  EXPECT_NEAR(f, dA / pi, 1e-15)
      << (f != 0 && gi::delta_form_factor_top(0, 0, 2 * dA) == f
              ? "straight up both cosines are 1 and r = 1: dF = dA / pi, but yours does not change when the cell's "
                "area dA doubles: multiply by the cell's area" + got
              : "straight up both cosines are 1 and r = 1: dF = dA / pi (did you forget the 1/pi?)" + got);
}

TEST(Ex7_1_DeltaTop, DenominatorIsSquared) {
  EXPECT_NEAR(gi::delta_form_factor_top(0.5, 0, dA), dA / (pi * 1.25 * 1.25), 1e-15)
      << "dF = dA / (pi (x^2 + y^2 + 1)^2): cos(theta_i) cos(theta_cell) / r^2 gives the power 2";
}

TEST(Ex7_1_DeltaTop, CornerCell) {
  EXPECT_NEAR(gi::delta_form_factor_top(1, -1, dA), dA / (9 * pi), 1e-15) << "at (1, -1): (1 + 1 + 1)^2 = 9";
}

TEST(Ex7_1_DeltaTop, TopFaceSumsToItsShareOfTheHemisphere) {
  const gi::HemicubeWeights w = gi::hemicube_weights(200);
  const double sum = std::accumulate(w.top.begin(), w.top.end(), 0.0);
  EXPECT_NEAR(sum, top_share, 1e-4) << "the top face sees " << top_share << " of the hemisphere (projected)";
}

TEST(Ex7_2_DeltaSide, NothingAtTheHorizon) {
  EXPECT_NEAR(gi::delta_form_factor_side(0.3, 0.0, dA), 0.0, 1e-18)
      << "at z = 0 the cell is in the patch's plane: cos(theta_i) = 0. Keep the factor z";
}

TEST(Ex7_2_DeltaSide, HalfwayUp) {
  EXPECT_NEAR(gi::delta_form_factor_side(0, 0.5, dA), 0.5 * dA / (pi * 1.25 * 1.25), 1e-15)
      << "dF = z dA / (pi (u^2 + z^2 + 1)^2)";
}

TEST(Ex7_2_DeltaSide, OffCentre) {
  const double u = 0.6, z = 0.4;
  const double d = u * u + z * z + 1;
  EXPECT_NEAR(gi::delta_form_factor_side(u, z, dA), z * dA / (pi * d * d), 1e-15)
      << "u runs across the face, z up it; both enter the distance";
}

TEST(Ex7_2_DeltaSide, TheSidesSeeTheRestOfTheHemisphere) {
  // Summed here from delta_form_factor_side alone, so that this test does not depend
  // on exercise 7.1: one half face at 100 x 50 cells, centred cells as the hemicube uses.
  const int res = 100;
  const double h = 2.0 / res;
  double side = 0;
  for (int row = 0; row < res / 2; ++row)
    for (int column = 0; column < res; ++column)
      side += gi::delta_form_factor_side(-1 + (column + 0.5) * h, (row + 0.5) * h, h * h);
  EXPECT_NEAR(4 * side, 1 - top_share, 1e-3)
      << "the four half faces see what the top face does not: 1 - " << top_share << " of the hemisphere";
}
