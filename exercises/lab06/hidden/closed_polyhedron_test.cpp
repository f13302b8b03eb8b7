// Hidden graded tests of lab 6 (the autograder's): the contour integral over shapes
// that close around the point, and the differential form factor against Howell's
// exact formula for small patches. One point per test.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "gi/core/rng.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "support/print.hpp"

using gi::vec3;

TEST(Ex6_2_Closed, ABoxOverThePointSeesTheWholeHemisphere) {
  // The point sits in the middle of the floor of the box [-1, 1]^2 x [0, h]: the top
  // and the four walls fill its hemisphere, whatever the box's height and however it
  // is turned (the rotation applies to the point's normal too). Each face is listed
  // counter-clockwise seen from inside.
  gi::Rng rng(707);
  for (int k = 0; k < 20; ++k) {
    const double h = 0.2 + 3 * rng.uniform(), a = 2 * gi::pi * rng.uniform(), b = gi::pi * rng.uniform();
    const auto turn = [&](vec3 v) {
      v = vec3(std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y, v.z);
      return vec3(v.x, std::cos(b) * v.y - std::sin(b) * v.z, std::sin(b) * v.y + std::cos(b) * v.z);
    };
    const vec3 c[8] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, h}, {1, -1, h}, {1, 1, h}, {-1, 1, h}};
    const int faces[5][4] = {{4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
    double sum = 0;
    for (const auto& f : faces) {
      std::array<vec3, 4> v;
      for (int i = 0; i < 4; ++i) v[i] = turn(c[f[i]]);
      sum += gi::contour_integral(turn({0, 0, 0}), turn({0, 0, 1}), v.data(), 4);
    }
    EXPECT_NEAR(sum, 1.0, 1e-10) << "box " << k << " (height " << h << "): its five faces fill the hemisphere";
  }
}

TEST(Ex6_1_SmallPatches, AgreeWithHowellsFormula) {
  // A small square patch facing the point, off its axis: the exact form factor is a
  // sum of four of Howell's corner rectangles; the integrand at the centre times the
  // area agrees with it to about (size / distance)^2.
  gi::Rng rng(808);
  for (int k = 0; k < 50; ++k) {
    const double x = 0.5 + 3 * rng.uniform(), y = 0.5 + 3 * rng.uniform(), c = 5 + 5 * rng.uniform(), s = 0.01;
    const auto corner = [&](double a, double b) { return gi::ff_point_to_parallel_rectangle_corner(a, b, c); };
    const double exact = corner(x + s, y + s) - corner(x - s, y + s) - corner(x + s, y - s) + corner(x - s, y - s);
    const double f = gi::form_factor_differential({0, 0, 0}, {0, 0, 1}, {x, y, c}, {0, 0, -1}, 4 * s * s, 1.0);
    EXPECT_NEAR(f, exact, 1e-5 * exact) << "patch " << k << ": F = cos_i cos_j / (pi r^2) A_j for a small far patch";
  }
}
