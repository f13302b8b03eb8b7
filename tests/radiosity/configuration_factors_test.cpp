#include "gi/radiosity/configuration_factors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "gi/core/math.hpp"

using gi::vec3;

namespace {

// The double area integral F_12 = 1/A_1 ∫∫ cos θ1 cos θ2 / (π r²) dA_2 dA_1 by the
// midpoint rule on n x n cells per rectangle: an independent check of the closed forms
// (second-order accurate away from shared edges).
double integrate(vec3 o1, vec3 u1, vec3 v1, vec3 o2, vec3 u2, vec3 v2, int n) {
  const vec3 n1 = gi::normalize(gi::cross(u1, v1)), n2 = gi::normalize(gi::cross(u2, v2));
  const double da1 = gi::length(gi::cross(u1, v1)) / (n * n), da2 = gi::length(gi::cross(u2, v2)) / (n * n);
  double sum = 0;
  for (int i = 0; i < n * n; ++i) {
    const vec3 p = o1 + ((i % n + 0.5) / n) * u1 + ((i / n + 0.5) / n) * v1;
    for (int j = 0; j < n * n; ++j) {
      const vec3 q = o2 + ((j % n + 0.5) / n) * u2 + ((j / n + 0.5) / n) * v2;
      const vec3 d = q - p;
      const double r2 = gi::dot(d, d);
      sum += std::max(0.0, gi::dot(n1, d)) * std::max(0.0, -gi::dot(n2, d)) / (r2 * r2) * da2;
    }
  }
  return sum * da1 / (std::numbers::pi * gi::length(gi::cross(u1, v1)));
}

}  // namespace

TEST(ConfigurationFactors, KnownValues) {
  EXPECT_NEAR(gi::ff_parallel_rectangles(1, 1, 1), 0.19982, 1e-5);
  EXPECT_NEAR(gi::ff_perpendicular_rectangles(1, 1, 1), 0.20004, 1e-5);
  EXPECT_NEAR(gi::ff_point_to_parallel_rectangle_corner(1e6, 1e6, 1), 0.25, 1e-6);
}

TEST(ConfigurationFactors, ParallelRectanglesAgreeWithQuadrature) {
  for (auto [a, b, c] : {std::array{1.0, 1.0, 1.0}, std::array{2.0, 0.5, 1.0}, std::array{1.0, 3.0, 0.7}}) {
    const double numeric = integrate({0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}, {0, b, 0}, {a, 0, 0}, 24);
    EXPECT_NEAR(gi::ff_parallel_rectangles(a, b, c), numeric, 2e-3 * numeric) << a << " " << b << " " << c;
  }
}

TEST(ConfigurationFactors, PerpendicularRectanglesAgreeWithQuadratureAndReciprocity) {
  // Rectangle 1 in the floor (width w along y), rectangle 2 in the wall x-z (height h),
  // common edge along x of length l.
  const double l = 1.5, w = 0.8, h = 1.2;
  // The integrand is singular along the shared edge, so the midpoint rule converges
  // only like 1/n; Richardson extrapolation 2 I(2n) - I(n) removes that first term.
  const auto at = [&](int n) { return integrate({0, 0, 0}, {l, 0, 0}, {0, w, 0}, {0, 0, 0}, {0, 0, h}, {l, 0, 0}, n); };
  const double numeric = 2 * at(48) - at(24);
  EXPECT_NEAR(gi::ff_perpendicular_rectangles(l, w, h), numeric, 1e-3 * numeric);
  // A_1 F_12 = A_2 F_21
  EXPECT_NEAR(w * gi::ff_perpendicular_rectangles(l, w, h), h * gi::ff_perpendicular_rectangles(l, h, w), 1e-12);
}

TEST(ConfigurationFactors, PointToRectangleAgreesWithQuadrature) {
  // The point at the origin looking up +z; the rectangle [0, a] x [0, b] at height c.
  const double a = 1.3, b = 0.6, c = 0.9;
  const int n = 400;
  double sum = 0;
  for (int j = 0; j < n * n; ++j) {
    const vec3 q((j % n + 0.5) / n * a, (j / n + 0.5) / n * b, c);
    const double r2 = gi::dot(q, q);
    sum += c * c / (r2 * r2) * (a * b / (n * n));
  }
  EXPECT_NEAR(gi::ff_point_to_parallel_rectangle_corner(a, b, c), sum / std::numbers::pi, 1e-6);
}

TEST(ConfigurationFactors, BadLengthsAreRejected) {
  EXPECT_THROW(gi::ff_parallel_rectangles(0, 1, 1), std::invalid_argument);
  EXPECT_THROW(gi::ff_perpendicular_rectangles(1, -1, 1), std::invalid_argument);
  EXPECT_THROW(gi::ff_point_to_parallel_rectangle_corner(1, 1, NAN), std::invalid_argument);
}
