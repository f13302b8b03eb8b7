// The analytic method against a catalogue of configurations with exact values (from
// configuration_factors.hpp, Howell's catalogue; independent numerical integration
// where the catalogue has only tables), through the public API: a FormFactorScene,
// form_factor_row with the default settings. Required: 1e-9 relative, or 1e-12
// absolute where F is tiny; and the method's own error estimate must cover its error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"

using gi::vec3;

namespace {

// The parallelogram o, o + u, o + u + v, o + v, facing u x v.
gi::Polygon quad(vec3 o, vec3 u, vec3 v) { return gi::make_polygon({o, o + u, o + u + v, o + v}); }

// F from polygons[0] to the sum of polygons[1..] by the public API, and the sum of
// the estimates of their errors.
struct Result {
  double value = 0, error = 0;
};
Result analytic(const std::vector<gi::Polygon>& polygons) {
  gi::FormFactorSettings settings;
  settings.method = gi::FormFactorMethod::Analytic;
  const gi::FormFactorScene scene(polygons);
  const gi::FormFactorRow row = gi::form_factor_row_with_diagnostics(scene, polygons[0], 0, settings);
  EXPECT_EQ(row.F, gi::form_factor_row(scene, polygons[0], 0, settings));
  Result r;
  for (std::size_t j = 1; j < polygons.size(); ++j) r.value += row.F[j], r.error += row.error[j];
  EXPECT_EQ(row.F[0], 0.0) << "F_ii";
  return r;
}

void expect_exact(const std::vector<gi::Polygon>& polygons, double exact, const std::string& what) {
  const Result r = analytic(polygons);
  const double allowed = std::max(1e-9 * exact, 1e-12);
  EXPECT_LE(std::abs(r.value - exact), allowed) << what << ": " << r.value << " against " << exact;
  // The estimate meets the tolerance (1e-10 by default) and covers the true error (the
  // reference's own round-off, 1e-14, aside).
  EXPECT_LE(r.error, allowed) << what;
  EXPECT_LE(std::abs(r.value - exact), r.error + 1e-14 * exact) << what << ": the estimate " << r.error
                                                                  << " is below the error";
}

// Two rectangles sharing the edge [0, l] along x, with included angle phi: the sender
// of width b in z = 0 (facing +z), the receiver of width a rising at phi from it.
std::vector<gi::Polygon> hinge(double l, double b, double a, double phi) {
  const vec3 up(0, std::cos(phi), std::sin(phi));
  return {quad({0, 0, 0}, {l, 0, 0}, {0, b, 0}), quad({0, 0, 0}, a * up, {l, 0, 0})};
}

// The hinge's F by an independent integration: Lambert's contour integral (exact from
// a point) over the sender with Gauss-Legendre rules graded toward the shared edge
// (y = b s^3) and toward its two ends (x = l (10 s^3 - 15 s^4 + 6 s^5)), where the
// integrand has logarithmic singularities. Returns the finer of two orders; `spread`
// gets their difference.
double hinge_by_graded_quadrature(double l, double b, const gi::Polygon& receiver, double& spread) {
  const auto at_order = [&](int n) {
    const gi::GaussRule& rule = gi::gauss_legendre(n);
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double s = rule.nodes[i], t = rule.nodes[j];
        const double x = l * s * s * s * (10 - 15 * s + 6 * s * s), dx = l * 30 * s * s * (1 - s) * (1 - s);
        const double y = b * t * t * t, dy = 3 * b * t * t;
        sum += rule.weights[i] * rule.weights[j] * dx * dy * gi::form_factor_point_to_polygon({x, y, 0}, {0, 0, 1}, receiver);
      }
    return sum / (l * b);
  };
  const double coarse = at_order(48), fine = at_order(64);
  spread = std::abs(fine - coarse);
  return fine;
}

}  // namespace

TEST(AnalyticCatalogue, DirectlyOpposedRectanglesNearMidAndFar) {
  for (double c : {1e-3, 0.05, 0.2, 1.0, 5.0, 100.0, 1e3, 1e6})
    expect_exact({quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({0, 0, c}, {0, 1, 0}, {1, 0, 0})},
                 gi::ff_parallel_rectangles(1, 1, c), "squares " + std::to_string(c) + " apart");
  for (double c : {0.01, 0.5, 20.0})
    expect_exact({quad({0, 0, 0}, {3, 0, 0}, {0, 0.4, 0}), quad({0, 0, c}, {0, 0.4, 0}, {3, 0, 0})},
                 gi::ff_parallel_rectangles(3, 0.4, c), "3 x 0.4 rectangles " + std::to_string(c) + " apart");
}

TEST(AnalyticCatalogue, OffsetAndUnequalParallelRectangles) {
  // Sender [0, 1] x [0, 2] at z = 0; receiver [s, s + 0.5] x [t, t + 1.5] at z.
  for (double scale : {0.05, 0.3, 1.0, 10.0, 1e3, 1e6}) {
    const double z = 0.7 * scale, s = 0.3 * scale, t = 1.1 * scale;
    expect_exact({quad({0, 0, 0}, {1, 0, 0}, {0, 2, 0}), quad({s, t, z}, {0, 1.5, 0}, {0.5, 0, 0})},
                 gi::ff_parallel_rectangles_offset(0, 1, 0, 2, s, s + 0.5, t, t + 1.5, z),
                 "offset, scale " + std::to_string(scale));
  }
  // Overlapping in projection, a hair apart: the near field at its nearest.
  expect_exact({quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({0.5, -0.2, 1e-3}, {0, 2, 0}, {2, 0, 0})},
               gi::ff_parallel_rectangles_offset(0, 1, 0, 1, 0.5, 2.5, -0.2, 1.8, 1e-3), "half over, 1e-3 apart");
}

TEST(AnalyticCatalogue, PerpendicularRectanglesSharingAnEdge) {
  // Sender in z = 0 over [0, l] x [0, w]; receiver in y = 0 over [0, l] x [0, h] in z.
  for (auto [l, w, h] : {std::array{1.0, 1.0, 1.0}, std::array{1.0, 0.1, 2.0}, std::array{2.0, 3.0, 0.5},
                         std::array{1.0, 1e3, 1.0}, std::array{1e-3, 1.0, 1.0}})
    expect_exact({quad({0, 0, 0}, {l, 0, 0}, {0, w, 0}), quad({0, 0, 0}, {0, 0, h}, {l, 0, 0})},
                 gi::ff_perpendicular_rectangles(l, w, h), "perpendicular " + std::to_string(w) + " on " + std::to_string(h));
}

TEST(AnalyticCatalogue, PerpendicularRectanglesNearMidAndFar) {
  // Sender in z = 0 over x in [x1, x1 + 1], y in [y1, y1 + 2]; receiver in x = 0 over
  // y in [e1, e1 + 1.5], z in [z1, z1 + 0.5], facing +x.
  for (double scale : {0.0, 0.01, 0.3, 1.0, 10.0, 1e3, 1e6}) {
    const double x1 = 0.2 * scale, y1 = 0.1 * scale, e1 = 0.5 * scale, z1 = 0.3 * scale;
    expect_exact({quad({x1, y1, 0}, {1, 0, 0}, {0, 2, 0}), quad({0, e1, z1}, {0, 1.5, 0}, {0, 0, 0.5})},
                 gi::ff_perpendicular_rectangles_offset(x1, x1 + 1, y1, y1 + 2, e1, e1 + 1.5, z1, z1 + 0.5),
                 "perpendicular offset, scale " + std::to_string(scale));
  }
}

TEST(AnalyticCatalogue, PointToPolygon) {
  // A sender of 1e-8 x 1e-8 is a differential area to 1e-16 (its F differs from the
  // point's by terms in (size / distance)^2).
  const double e = 1e-8;
  for (auto [a, b, c] : {std::array{1.3, 0.6, 0.9}, std::array{0.1, 0.1, 3.0}, std::array{40.0, 40.0, 0.02}}) {
    expect_exact({quad({-e / 2, -e / 2, 0}, {e, 0, 0}, {0, e, 0}), quad({0, 0, c}, {0, b, 0}, {a, 0, 0})},
                 gi::ff_point_to_parallel_rectangle_corner(a, b, c), "point to parallel rectangle");
    expect_exact({quad({-e / 2, -e / 2, 0}, {e, 0, 0}, {0, e, 0}), quad({0, c, 0}, {a, 0, 0}, {0, 0, b})},
                 gi::ff_point_to_perpendicular_rectangle_corner(a, b, c), "point to perpendicular rectangle");
  }
}

TEST(AnalyticCatalogue, SharedEdgesAtSeveralAngles) {
  // Against the graded quadrature above (agreeing with itself to 1e-11 between orders)
  // and, for 120 degrees, Howell's table C-16 to its six decimals (A = a/l, B = b/l,
  // from the plate of width b to the one of width a).
  for (double degrees : {30.0, 60.0, 90.0, 120.0, 150.0, 175.0}) {
    const double phi = degrees * std::numbers::pi / 180;
    const std::vector<gi::Polygon> plates = hinge(1.0, 0.7, 1.3, phi);
    double spread = 0;
    const double reference = hinge_by_graded_quadrature(1.0, 0.7, plates[1], spread);
    ASSERT_LT(spread, 1e-11 * reference) << degrees;
    expect_exact(plates, reference, std::to_string(degrees) + " degrees");
  }
  EXPECT_NEAR(gi::ff_perpendicular_rectangles(1, 0.7, 1.3), analytic(hinge(1.0, 0.7, 1.3, std::numbers::pi / 2)).value,
              1e-12);
  const double phi = 2 * std::numbers::pi / 3;
  for (auto [A, B, table] : {std::array{1.0, 1.0, 0.086615}, std::array{2.0, 0.4, 0.153457},
                             std::array{0.4, 2.0, 0.030691}, std::array{0.05, 20.0, 0.000567}})
    EXPECT_NEAR(analytic(hinge(1.0, B, A, phi)).value, table, 6e-7) << A << " " << B;
}

TEST(AnalyticCatalogue, ThinOnWide) {
  // A strip on the edge of a wide plate, both ways round: a fixed Gauss rule over the
  // sender was -14% here.
  for (double w : {1e-2, 1e-4, 1e-6}) {
    expect_exact({quad({0, 0, 0}, {1, 0, 0}, {0, w, 0}), quad({0, 0, 0}, {0, 0, 1}, {1, 0, 0})},
                 gi::ff_perpendicular_rectangles(1, w, 1), "strip " + std::to_string(w) + " to plate");
    expect_exact({quad({0, 0, 0}, {0, 0, 1}, {1, 0, 0}), quad({0, 0, 0}, {1, 0, 0}, {0, w, 0})},
                 gi::ff_perpendicular_rectangles(1, 1, w), "plate to strip " + std::to_string(w));
  }
  // A thin strip above the middle of a wide plate, and the other way.
  expect_exact({quad({0, 0, 0}, {10, 0, 0}, {0, 10, 0}), quad({4.99, 3, 0.1}, {0, 4, 0}, {0.02, 0, 0})},
               gi::ff_parallel_rectangles_offset(0, 10, 0, 10, 4.99, 5.01, 3, 7, 0.1), "wide to thin");
  expect_exact({quad({4.99, 3, 0}, {0.02, 0, 0}, {0, 4, 0}), quad({0, 0, 0.1}, {0, 10, 0}, {10, 0, 0})},
               gi::ff_parallel_rectangles_offset(4.99, 5.01, 3, 7, 0, 10, 0, 10, 0.1), "thin to wide");
}

TEST(AnalyticCatalogue, PolygonsBuiltFromSeveralQuads) {
  // An L-shaped receiver, [0, 2] x [0, 2] without [1, 2] x [1, 2], as two quads, 0.5
  // above a unit square sender: F = F(to the 2 x 2) - F(to the missing corner).
  const double exact = gi::ff_parallel_rectangles_offset(0, 1, 0, 1, 0, 2, 0, 2, 0.5) -
                       gi::ff_parallel_rectangles_offset(0, 1, 0, 1, 1, 2, 1, 2, 0.5);
  expect_exact({quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({0, 0, 0.5}, {0, 1, 0}, {2, 0, 0}),
                quad({0, 1, 0.5}, {0, 1, 0}, {1, 0, 0})},
               exact, "square to an L of two quads");
  // The L as the sender: A_L F_(L,j) = sum over its quads A_k F_kj.
  gi::FormFactorSettings analytic_settings;
  analytic_settings.method = gi::FormFactorMethod::Analytic;
  const gi::Polygon a = quad({0, 0, 0}, {2, 0, 0}, {0, 1, 0}), b = quad({0, 1, 0}, {1, 0, 0}, {0, 1, 0});
  const gi::Polygon target = quad({0, 0, 0.5}, {0, 1, 0}, {1, 0, 0});
  const gi::FormFactorScene scene({a, b, target});
  const double from_l = (a.area * gi::form_factor_row(scene, a, 0, analytic_settings)[2] +
                         b.area * gi::form_factor_row(scene, b, 1, analytic_settings)[2]) /
                        (a.area + b.area);
  EXPECT_NEAR(from_l * (a.area + b.area), exact * 1.0, 1e-9 * exact) << "reciprocity over the L";
}

TEST(AnalyticCatalogue, ReciprocityAndTheDiagonal) {
  // A_i F_ij = A_j F_ji for skew pairs with no closed form, and F_ii = 0.
  const std::vector<gi::Polygon> polygons = {
      quad({0, 0, 0}, {1, 0, 0}, {0.3, 1, 0}), quad({0.2, 0.1, 0.8}, {0.1, 1.2, -0.2}, {0.9, 0, 0.3}),
      quad({1, 0, 0}, {0, 0, 1}, {0.2, 1, 0.4})};
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    EXPECT_EQ(gi::form_factor_analytic_adaptive(polygons[i], polygons[i]).value, 0.0);
    for (std::size_t j = 0; j < polygons.size(); ++j) {
      if (i == j) continue;
      const double ij = polygons[i].area * gi::form_factor_analytic_adaptive(polygons[i], polygons[j]).value;
      const double ji = polygons[j].area * gi::form_factor_analytic_adaptive(polygons[j], polygons[i]).value;
      EXPECT_NEAR(ij, ji, 2e-10 * std::max(ij, ji)) << i << " " << j;
    }
  }
}
