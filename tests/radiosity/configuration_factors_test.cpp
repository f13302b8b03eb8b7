#include "gi/radiosity/form_factors/configuration_factors.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "gi/core/math.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"
#include "gi/render/sampler_study.hpp"

using gi::vec3;
using ld = gi::wide;

namespace {

const ld pi_ld = gi::pi_wide;

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

// The same integral, for rectangles far apart, by a Gauss-Legendre rule of order 12 in
// each of the four coordinates, summed in gi::wide: the kernel is smooth and
// positive there, so nothing cancels and the rule is exact to round-off. `kernel`
// takes a point of each rectangle in the rectangles' own coordinates.
ld gauss_4d(const std::array<double, 8>& box, const std::function<ld(ld, ld, ld, ld)>& kernel) {
  const gi::GaussRule& rule = gi::gauss_legendre(12);
  const auto at = [&](int axis, int i) { return box[2 * axis] + rule.nodes[i] * ld(box[2 * axis + 1] - box[2 * axis]); };
  ld sum = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 12; ++k)
        for (int l = 0; l < 12; ++l)
          sum += ld(rule.weights[i]) * rule.weights[j] * rule.weights[k] * rule.weights[l] *
                 kernel(at(0, i), at(1, j), at(2, k), at(3, l));
  return sum * (box[5] - box[4]) * (box[7] - box[6]);  // the mean over both, times A_2
}

// Directly opposed a x b rectangles c apart, by Gauss over both: F = 1/A_1 ∫∫ c² / (π r⁴).
ld parallel_by_gauss(double a, double b, double c) {
  return gauss_4d({0, a, 0, b, 0, a, 0, b}, [c](ld x, ld y, ld xi, ld eta) {
    const ld r2 = (x - xi) * (x - xi) + (y - eta) * (y - eta) + ld(c) * c;
    return ld(c) * c / (pi_ld * r2 * r2);
  });
}

// The textbook forms' values, computed once with Python's mpmath at 50 digits (the
// forms as Howell prints them, whose cancellation costs nothing at that precision) and
// rounded to 20: the directly opposed a x b rectangles c apart, {a, b, c / a, F} ...
struct ParallelValue {
  double a, b, c_over_a;
  ld F;
};
constexpr ParallelValue parallel_textbook[] = {
    {1.0, 1.0, 0.0001, 0.99980007097778848714L},
    {1.0, 1.0, 0.01, 0.98041660292597326744L},
    {1.0, 1.0, 0.3, 0.57953076066913190395L},
    {1.0, 1.0, 1.0, 0.19982489569838738304L},
    {1.0, 1.0, 2.0, 0.068589588818552447785L},
    {1.0, 1.0, 3.0, 0.032971397219497298148L},
    {1.0, 1.0, 10.0, 0.0031620568387576016251L},
    {2.0, 0.3, 0.0001, 0.99923390853836449692L},
    {2.0, 0.3, 0.01, 0.92712873913294722986L},
    {2.0, 0.3, 0.3, 0.19149194801653993376L},
    {2.0, 0.3, 1.0, 0.03724743217417166116L},
    {2.0, 0.3, 2.0, 0.011048794809324570079L},
    {2.0, 0.3, 3.0, 0.0051166300653029837986L},
    {2.0, 0.3, 10.0, 0.0004758471340273463176L},
};
// ... and the perpendicular rectangles sharing an edge of length 1, F[w][h] from the one of
// width W = perpendicular_ratios[w] to the one of height H = perpendicular_ratios[h].
constexpr double perpendicular_ratios[] = {0.01, 0.1, 1.0, 10.0, 100.0};
constexpr ld perpendicular_textbook[5][5] = {
    {0.29179006733692164944L, 0.47060041563641600304L, 0.4895849268506683038L, 0.49027536206913443456L, 0.4902832270260357069L},
    {0.047060041563641598671L, 0.28188780678790142968L, 0.43251369400685855234L, 0.43938730070715551218L, 0.43946594635079324487L},
    {0.0048958492685066831399L, 0.043251369400685857635L, 0.20004377607540315424L, 0.24920948579031059959L, 0.2499920427833167927L},
    {0.00049027536206913444477L, 0.0043938730070715553657L, 0.024920948579031059959L, 0.055023979528410589779L, 0.060454076984224806511L},
    {0.00004902832270260357171L, 0.00043946594635079326927L, 0.002499920427833167927L, 0.0060454076984224806511L, 0.0091651110286947807933L},
};

void expect_relative(double value, ld reference, double tolerance, const std::string& what) {
  EXPECT_LE(std::abs(static_cast<ld>(value) - reference) / reference, tolerance)
      << what << ": " << value << " against " << static_cast<double>(reference);
}

}  // namespace

TEST(ConfigurationFactors, KnownValues) {
  EXPECT_NEAR(gi::ff_parallel_rectangles(1, 1, 1), 0.19982, 1e-5);
  EXPECT_NEAR(gi::ff_perpendicular_rectangles(1, 1, 1), 0.20004, 1e-5);
  EXPECT_NEAR(gi::ff_point_to_parallel_rectangle_corner(1e6, 1e6, 1), 0.25, 1e-6);
  EXPECT_NEAR(gi::ff_point_to_perpendicular_rectangle_corner(1e6, 1e6, 1e-6), 0.25, 1e-6);
}

TEST(ConfigurationFactors, ParallelRectanglesAgreeWithQuadrature) {
  for (auto [a, b, c] : {std::array{1.0, 1.0, 1.0}, std::array{2.0, 0.5, 1.0}, std::array{1.0, 3.0, 0.7}}) {
    const double numeric = integrate({0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}, {0, b, 0}, {a, 0, 0}, 24);
    EXPECT_NEAR(gi::ff_parallel_rectangles(a, b, c), numeric, 2e-3 * numeric) << a << " " << b << " " << c;
  }
}

TEST(ConfigurationFactors, ParallelRectanglesKeepTheirDigitsFromTouchingTo1e6Apart) {
  // Near and middle: the textbook form's values at 50 digits (above). Far: Gauss over
  // both rectangles, positive terms that nothing cancels. The textbook form in double
  // gives +9e-5 at c = 1000 a and exactly 0 at 10^6.
  for (const ParallelValue& v : parallel_textbook)
    expect_relative(gi::ff_parallel_rectangles(v.a, v.b, v.c_over_a * v.a), v.F, 1e-13,
                    "textbook, c/a = " + std::to_string(v.c_over_a));
  for (double c : {10.0, 30.0, 100.0, 1e3, 1e4, 1e6})
    expect_relative(gi::ff_parallel_rectangles(1, 0.5, c), parallel_by_gauss(1, 0.5, c), 1e-13,
                    "Gauss, c = " + std::to_string(c));
  // The series takes over at c^2 = 4 (a^2 + b^2): both sides of the switch agree.
  const double switch_c = 2 * std::sqrt(2.0), at_switch = gi::ff_parallel_rectangles(1, 1, switch_c);
  EXPECT_NEAR(gi::ff_parallel_rectangles(1, 1, switch_c * (1 - 1e-15)), at_switch, 1e-14 * at_switch);
  EXPECT_NEAR(gi::ff_parallel_rectangles(1, 1, switch_c * (1 + 1e-15)), at_switch, 1e-14 * at_switch);
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

TEST(ConfigurationFactors, PerpendicularRectanglesKeepTheirDigitsAtEveryRatio) {
  // Against the textbook form's values at 50 digits (above); at the extremes, against
  // the double contour integral (a different formula) and reciprocity.
  for (int w = 0; w < 5; ++w)
    for (int h = 0; h < 5; ++h) {
      const double W = perpendicular_ratios[w], H = perpendicular_ratios[h];
      expect_relative(gi::ff_perpendicular_rectangles(1, W, H), perpendicular_textbook[w][h], 1e-13,
                      "W = " + std::to_string(W) + ", H = " + std::to_string(H));
    }
  for (double W : {1e-6, 1e-3, 1e3, 1e6})
    for (double H : {1e-6, 1e-3, 1e3, 1e6}) {
      const gi::Polygon floor = gi::make_polygon({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, W, 0), vec3(0, W, 0)});
      const gi::Polygon wall = gi::make_polygon({vec3(0, 0, 0), vec3(0, 0, H), vec3(1, 0, H), vec3(1, 0, 0)});
      const double f = gi::ff_perpendicular_rectangles(1, W, H);
      EXPECT_NEAR(f, gi::form_factor_analytic_adaptive(floor, wall, 1e-12).value, 1e-10 * f) << W << " " << H;
      EXPECT_NEAR(W * f, H * gi::ff_perpendicular_rectangles(1, H, W), 1e-14 * W * f) << W << " " << H;
    }
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

TEST(ConfigurationFactors, PointToPerpendicularRectangleAgreesWithTheContourIntegral) {
  // The point at the origin looking up +z; the rectangle x in [0, a], z in [0, b] in the
  // plane y = c, facing the point. Lambert's contour integral is exact from a point.
  for (auto [a, b, c] : {std::array{1.3, 0.6, 0.9}, std::array{0.2, 3.0, 0.01}, std::array{5.0, 0.1, 40.0}}) {
    const gi::Polygon rectangle = gi::make_polygon({vec3(0, c, 0), vec3(a, c, 0), vec3(a, c, b), vec3(0, c, b)});
    const double contour = gi::form_factor_point_to_polygon({0, 0, 0}, {0, 0, 1}, rectangle);
    EXPECT_NEAR(gi::ff_point_to_perpendicular_rectangle_corner(a, b, c), contour, 1e-14 + 1e-12 * contour);
  }
  // Far away F -> a b^2 / (2 pi c^3) (cos_1 = z / r, cos_2 = c / r, r ~ c): the textbook
  // form's two arctangents cancel there, 1e-6 of each other at c = 1000.
  for (double c : {1e3, 1e6}) {
    const double leading = 1.0 * 0.5 * 0.5 / (2 * std::numbers::pi * c * c * c);
    EXPECT_NEAR(gi::ff_point_to_perpendicular_rectangle_corner(1, 0.5, c), leading, 1e-5 * leading);
  }
}

TEST(ConfigurationFactors, TheSamplerStudysSquareLightAgreesWithTheCornerFactorAndTheContour) {
  // The sampler study (gi/core/samplers) keeps its own closed form, the floors below
  // radiosity being unable to call this one: four corner rectangles, and Lambert's
  // contour integral of the square seen from the point below its centre.
  for (auto [a, h] : {std::array{1.0, 1.0}, std::array{0.3, 2.0}, std::array{8.0, 0.5}}) {
    const double four_corners = 4 * gi::ff_point_to_parallel_rectangle_corner(a / 2, a / 2, h);
    const gi::Polygon square = gi::make_polygon(
        {vec3(-a / 2, -a / 2, h), vec3(-a / 2, a / 2, h), vec3(a / 2, a / 2, h), vec3(a / 2, -a / 2, h)});
    const double contour = gi::form_factor_point_to_polygon({0, 0, 0}, {0, 0, 1}, square);
    EXPECT_NEAR(gi::form_factor_point_to_centred_square(a, h), four_corners, 1e-14) << "a = " << a << ", h = " << h;
    EXPECT_NEAR(gi::form_factor_point_to_centred_square(a, h), contour, 1e-13) << "a = " << a << ", h = " << h;
  }
}

TEST(ConfigurationFactors, OffsetParallelRectanglesNearAndFar) {
  // Aligned, they are the directly opposed case.
  EXPECT_NEAR(gi::ff_parallel_rectangles_offset(0, 2, 0, 0.5, 0, 2, 0, 0.5, 0.7), gi::ff_parallel_rectangles(2, 0.5, 0.7),
              1e-14);
  // Unequal and offset: against Gauss over both at 1.5 sizes and beyond the switch to
  // the far rule at 30 sizes, with the two rules' results continuous there.
  for (double scale : {1.5, 10.0, 29.0, 31.0, 1e3, 1e6}) {
    const double z = 0.7 * scale, s = 0.3 * scale, t = 1.1 * scale;
    const ld exact = gauss_4d({0, 1, 0, 2, s, s + 0.5, t, t + 1.5}, [z](ld x, ld y, ld xi, ld eta) {
      const ld r2 = (x - xi) * (x - xi) + (y - eta) * (y - eta) + ld(z) * z;
      return ld(z) * z / (pi_ld * r2 * r2);
    });
    expect_relative(gi::ff_parallel_rectangles_offset(0, 1, 0, 2, s, s + 0.5, t, t + 1.5, z), exact,
                    scale < 2 ? 1e-9 : 1e-12, "scale " + std::to_string(scale));
  }
  // Superposition: the receiver cut in two receives the same.
  const double whole = gi::ff_parallel_rectangles_offset(0, 1, 0, 1, -0.3, 0.8, 0.2, 1.4, 0.4);
  const double parts = gi::ff_parallel_rectangles_offset(0, 1, 0, 1, -0.3, 0.25, 0.2, 1.4, 0.4) +
                       gi::ff_parallel_rectangles_offset(0, 1, 0, 1, 0.25, 0.8, 0.2, 1.4, 0.4);
  EXPECT_NEAR(whole, parts, 1e-14);
}

TEST(ConfigurationFactors, OffsetPerpendicularRectanglesNearAndFar) {
  // Sharing the whole edge, they are the perpendicular case.
  EXPECT_NEAR(gi::ff_perpendicular_rectangles_offset(0, 0.8, 0, 1.5, 0, 1.5, 0, 1.2),
              gi::ff_perpendicular_rectangles(1.5, 0.8, 1.2), 1e-14);
  // Near: against the analytic method (the double contour integral, a different
  // formula). Far: against Gauss over both rectangles, across the switch at 30 sizes.
  for (double scale : {0.0, 0.5, 1.5}) {
    const double x1 = 0.2 * scale, y1 = 0.1 * scale, e1 = 0.5 * scale, z1 = 0.3 * scale;
    const gi::Polygon sender = gi::make_polygon({vec3(x1, y1, 0), vec3(x1 + 1, y1, 0), vec3(x1 + 1, y1 + 2, 0), vec3(x1, y1 + 2, 0)});
    const gi::Polygon receiver = gi::make_polygon({vec3(0, e1, z1), vec3(0, e1 + 1.5, z1), vec3(0, e1 + 1.5, z1 + 0.5), vec3(0, e1, z1 + 0.5)});
    const double f = gi::ff_perpendicular_rectangles_offset(x1, x1 + 1, y1, y1 + 2, e1, e1 + 1.5, z1, z1 + 0.5);
    EXPECT_NEAR(f, gi::form_factor_analytic_adaptive(sender, receiver, 1e-12).value, 1e-11 * f) << scale;
  }
  for (double scale : {10.0, 29.0, 31.0, 1e3, 1e6}) {
    const double x1 = 0.2 * scale, y1 = 0.1 * scale, e1 = 0.5 * scale, z1 = 0.3 * scale;
    const ld exact = gauss_4d({x1, x1 + 1, y1, y1 + 2, e1, e1 + 1.5, z1, z1 + 0.5}, [](ld x, ld y, ld eta, ld z) {
      const ld r2 = x * x + (y - eta) * (y - eta) + z * z;
      return x * z / (pi_ld * r2 * r2);
    });
    expect_relative(gi::ff_perpendicular_rectangles_offset(x1, x1 + 1, y1, y1 + 2, e1, e1 + 1.5, z1, z1 + 0.5), exact,
                    1e-12, "scale " + std::to_string(scale));
  }
  // Superposition along the common axis.
  const double whole = gi::ff_perpendicular_rectangles_offset(0, 1, 0, 1, -0.5, 2, 0.1, 0.9);
  const double parts = gi::ff_perpendicular_rectangles_offset(0, 1, 0, 1, -0.5, 0.4, 0.1, 0.9) +
                       gi::ff_perpendicular_rectangles_offset(0, 1, 0, 1, 0.4, 2, 0.1, 0.9);
  EXPECT_NEAR(whole, parts, 1e-14);
}

TEST(ConfigurationFactors, BadLengthsAreRejected) {
  EXPECT_THROW(gi::ff_parallel_rectangles(0, 1, 1), std::invalid_argument);
  EXPECT_THROW(gi::ff_perpendicular_rectangles(1, -1, 1), std::invalid_argument);
  EXPECT_THROW(gi::ff_point_to_parallel_rectangle_corner(1, 1, NAN), std::invalid_argument);
  EXPECT_THROW(gi::ff_point_to_perpendicular_rectangle_corner(1, INFINITY, 1), std::invalid_argument);
  EXPECT_THROW(gi::ff_parallel_rectangles_offset(1, 0, 0, 1, 0, 1, 0, 1, 1), std::invalid_argument);  // x2 < x1
  EXPECT_THROW(gi::ff_parallel_rectangles_offset(0, 1, 0, 1, 0, 1, 0, 1, 0), std::invalid_argument);  // in one plane
  EXPECT_THROW(gi::ff_perpendicular_rectangles_offset(-0.5, 1, 0, 1, 0, 1, 0, 1), std::invalid_argument);  // crosses
}
