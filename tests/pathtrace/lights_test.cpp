// Light sampling: points uniform over each light's area (or the cap of a sphere that
// can be seen), lights chosen by power, and next-event estimation against the closed
// forms of the light a point receives.
#include "gi/pathtrace/lights.hpp"

#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/pathtrace/next_event.hpp"
#include "support/statistics.hpp"

using gi::vec2;
using gi::vec3;
namespace t = gi::testing;

namespace {

// Three chi-square tests in this file: each at the Sidak level for a 1% chance of any
// false failure among them.
const double significance = t::sidak_significance(0.01, 3);

gi::Material glow(gi::Color radiance) {
  gi::Material m;
  m.diffuse = gi::Color(0.0);
  m.emission = radiance;
  return m;
}

// A tilted parallelogram light, a triangle light and a sphere light.
gi::Scene three_lights() {
  gi::Scene s;
  const int a = s.add(glow(gi::Color(1.0))), b = s.add(glow(gi::Color(3.0))), c = s.add(glow(gi::Color(0.5)));
  s.add(gi::Quad{{-1, 2, 0}, {2, 0.3, 0}, {0.4, 0, 1.5}, a});
  s.add(gi::Triangle{{2, 1, 1}, {3, 1.2, 1}, {2.2, 1.5, 2.5}, b});
  s.add(gi::Sphere{{0, 4, -2}, 0.7, c});
  return s;
}

// Corner rectangle a x b at height c above a point, parallel to the point's surface:
// F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
// A = a/c, B = b/c (Howell's catalogue, B-3).
double corner_rectangle_form_factor(double a, double b, double c) {
  const double A = a / c, B = b / c, sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * gi::pi);
}

}  // namespace

TEST(Lights, EveryEmitterIsALightWithAMaterialOfItsOwn) {
  gi::Scene s = three_lights();
  const int grey = s.add(gi::Material{});
  s.add(gi::Quad{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, grey});
  s.add(gi::Quad{{5, 5, 5}, {1, 0, 0}, {0, 0, -1}, 0});  // a second quad sharing the first light's material
  const gi::Lights lights = gi::find_lights(s);
  ASSERT_EQ(lights.lights.size(), 4u);
  // Triangles first, then quads, then spheres.
  EXPECT_EQ(lights.of_material[s.triangles[0].material], 0);
  EXPECT_EQ(lights.of_material[s.quads[0].material], 1);
  EXPECT_EQ(lights.of_material[s.quads[2].material], 2);
  EXPECT_EQ(lights.of_material[s.spheres[0].material], 3);
  EXPECT_NE(s.quads[0].material, s.quads[2].material);
  EXPECT_EQ(lights.of_material[grey], -1);
  // Chosen in proportion to power pi A L: the quads' areas, the triangle's, the sphere's.
  double total = 0;
  std::vector<double> power;
  for (const gi::Light& l : lights.lights) power.push_back(l.area * l.radiance.x), total += power.back();
  for (std::size_t k = 0; k < power.size(); ++k)
    EXPECT_NEAR(gi::discrete_pdf(lights.choice, int(k)), power[k] / total, 1e-12);
  EXPECT_NEAR(lights.lights[3].area, 4 * gi::pi * 0.49, 1e-12);
}

TEST(Lights, BadEmittersAreRefused) {
  gi::Scene s;
  gi::Material bad = glow(gi::Color(-1.0));
  s.materials.push_back(bad);
  EXPECT_THROW(gi::find_lights(s), std::invalid_argument);
  gi::Scene p;
  p.add(gi::Plane{{0, 0, 0}, {0, 1, 0}, p.add(glow(gi::Color(1.0)))});
  EXPECT_THROW(gi::find_lights(p), std::invalid_argument);
}

TEST(Lights, QuadAndTrianglePointsAreUniformOverTheArea) {
  gi::Scene s = three_lights();
  const gi::Lights lights = gi::find_lights(s);
  const gi::Quad& q = s.quads[0];
  const gi::Triangle& tri = s.triangles[0];
  gi::Rng rng(3);
  std::vector<vec2> quad_st, triangle_b;
  for (int k = 0; k < 200000; ++k) {
    const gi::LightSample y =
        gi::sample_light(lights, s, vec3(0.5, -1, 0.5), rng.uniform(), {rng.uniform(), rng.uniform()});
    ASSERT_NEAR(y.pdf_area, gi::light_pdf_area(lights, s, y.light, vec3(0.5, -1, 0.5)), 1e-12);
    if (y.light == 1) {
      // (s, t) with y = corner + s edge_u + t edge_v, by Cramer's rule in the plane.
      const vec3 p = y.point - q.corner, n = gi::cross(q.edge_u, q.edge_v);
      quad_st.push_back(vec2(gi::dot(gi::cross(p, q.edge_v), n), gi::dot(gi::cross(q.edge_u, p), n)) / gi::dot(n, n));
      ASSERT_NEAR(gi::dot(y.normal, gi::normalize(n)), 1.0, 1e-12);
      ASSERT_NEAR(y.pdf_area, gi::discrete_pdf(lights.choice, 1) / gi::area(q), 1e-12);
    } else if (y.light == 0) {
      const vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, p = y.point - tri.a, n = gi::cross(e1, e2);
      triangle_b.push_back(vec2(gi::dot(gi::cross(p, e2), n), gi::dot(gi::cross(e1, p), n)) / gi::dot(n, n));
    }
  }
  const double nq = double(quad_st.size());
  EXPECT_GT(t::chi_square_test(t::histogram_2d(quad_st, {0, 0}, {1, 1}, 10, 10),
                               t::expected_2d([](vec2) { return 1.0; }, {0, 0}, {1, 1}, 10, 10, nq))
                .p_value,
            significance);
  // Barycentric (b1, b2): density 2 below the diagonal, the diagonal cells cut in half.
  const int n = 10;
  std::vector<double> expected(n * n + 1, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      expected[j * n + i] = triangle_b.size() * (i + j < n - 1 ? 2.0 : i + j == n - 1 ? 1.0 : 0.0) / (n * n);
  EXPECT_GT(t::chi_square_test(t::histogram_2d(triangle_b, {0, 0}, {1, 1}, n, n), expected).p_value, significance);
}

TEST(Lights, SpherePointsAreUniformOverTheCapThePointSees) {
  gi::Scene s = three_lights();
  const gi::Lights lights = gi::find_lights(s);
  const gi::Sphere& sphere = s.spheres[0];
  const vec3 x(0.4, 0.8, -0.5);
  const double d = gi::length(x - sphere.center), cos_max = sphere.radius / d;
  const vec3 axis = (x - sphere.center) / d;
  const vec3 u_axis = gi::normalize(gi::cross(axis, vec3(1, 0, 0))), v_axis = gi::cross(axis, u_axis);
  gi::Rng rng(4);
  std::vector<vec2> cap;
  for (int k = 0; k < 200000; ++k) {
    const gi::LightSample y = gi::sample_light(lights, s, x, rng.uniform(), {rng.uniform(), rng.uniform()});
    if (y.light != 2) continue;
    const vec3 w = (y.point - sphere.center) / sphere.radius;
    ASSERT_NEAR(gi::length(w), 1.0, 1e-12);
    ASSERT_GE(gi::dot(w, axis), cos_max - 1e-12) << "on the cap x can see";
    ASSERT_GE(gi::dot(y.normal, x - y.point), -1e-9) << "facing x";
    ASSERT_NEAR(y.pdf_area * 2 * gi::pi * sphere.radius * sphere.radius * (1 - cos_max),
                gi::discrete_pdf(lights.choice, 2), 1e-12);
    double phi = std::atan2(gi::dot(w, v_axis), gi::dot(w, u_axis));
    cap.push_back({gi::dot(w, axis), phi < 0 ? phi + 2 * gi::pi : phi});
  }
  // Cells of (cos, phi) over the cap alone, each the same area: the counts are equal.
  const vec2 lo(cos_max, 0), hi(1, 2 * gi::pi);
  EXPECT_GT(t::chi_square_test(
                t::histogram_2d(cap, lo, hi, 8, 16),
                t::expected_2d([](vec2) { return 1.0; }, lo, hi, 8, 16, double(cap.size()) / ((hi.x - lo.x) * hi.y)))
                .p_value,
            significance);
}

TEST(Lights, NextEventEstimationMatchesTheFormFactorOfASquareLight) {
  // A Lambertian point (rho = 0.6) under a square light of side 2 at height 1.5, centred
  // above it and facing it, radiance L = 2: the reflected radiance is rho L F, with F the
  // point-to-square form factor, four corner rectangles of 1 x 1. 4000 estimates of 50
  // samples each; 5 standard errors: a false failure about once in 2 million seeds.
  gi::Scene s;
  s.add(gi::Quad{{-1, 1.5, -1}, {2, 0, 0}, {0, 0, 2}, s.add(glow(gi::Color(2.0)))});  // normal -y: facing down
  const gi::Lights lights = gi::find_lights(s);
  const gi::Bsdf rho{gi::BsdfKind::Lambertian, gi::Color(0.6), 1.0};
  const vec3 x(0, 0, 0), n(0, 1, 0), wo = gi::normalize(vec3(0.3, 1, 0.2));
  const double expected = 0.6 * 2.0 * 4 * corner_rectangle_form_factor(1, 1, 1.5);
  gi::Rng rng(5);
  std::vector<double> estimates;
  for (int k = 0; k < 4000; ++k) {
    double sum = 0;
    for (int j = 0; j < 50; ++j) {
      const gi::LightSample y = gi::sample_light(lights, s, x, rng.uniform(), {rng.uniform(), rng.uniform()});
      sum += gi::next_event_estimate(rho, x, n, wo, y).estimate.x;
    }
    estimates.push_back(sum / 50);
  }
  const t::Estimate e = t::estimate(estimates);
  EXPECT_NEAR(e.mean, expected, 5 * e.standard_error);
  EXPECT_LT(e.standard_error, 0.002 * expected) << "the test must be able to see a 1% error";
}

TEST(Lights, NextEventEstimationMatchesTheClosedFormOfASphereLight) {
  // A sphere of radius r and radiance L at distance d straight above a Lambertian point
  // gives it irradiance E = pi L (r / d)^2, so the reflected radiance is rho L (r / d)^2.
  gi::Scene s;
  const double r = 0.5, d = 2.0;
  s.add(gi::Sphere{{0, d, 0}, r, s.add(glow(gi::Color(3.0)))});
  const gi::Lights lights = gi::find_lights(s);
  const gi::Bsdf rho{gi::BsdfKind::Lambertian, gi::Color(0.5), 1.0};
  const vec3 x(0, 0, 0), n(0, 1, 0), wo(0, 1, 0);
  gi::Rng rng(6);
  std::vector<double> estimates;
  for (int k = 0; k < 4000; ++k) {
    double sum = 0;
    for (int j = 0; j < 50; ++j)
      sum += gi::next_event_estimate(rho, x, n, wo,
                                     gi::sample_light(lights, s, x, rng.uniform(), {rng.uniform(), rng.uniform()}))
                 .estimate.x;
    estimates.push_back(sum / 50);
  }
  const t::Estimate e = t::estimate(estimates);
  EXPECT_NEAR(e.mean, 0.5 * 3.0 * (r / d) * (r / d), 5 * e.standard_error);
}
