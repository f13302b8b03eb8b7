// Graded tests of exercise 14.4: next-event estimation with the light's density in area
// measure. One point per test.
#include "gi/pathtrace/next_event.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gi/core/rng.hpp"
#include "support/print.hpp"
#include "support/statistics.hpp"

using gi::vec3;

namespace {

// A Lambertian point at the origin facing +y, seen from wo; a light point y above it
// whose normal is tilted away from the direction to x, so that every cosine matters.
const gi::Bsdf rho{gi::BsdfKind::Lambertian, gi::Color(0.6), 1.0};
const vec3 x(0, 0, 0), n(0, 1, 0), wo = gi::normalize(vec3(0.2, 1, 0.4));
const vec3 y_point(1, 2, 0.5);
const vec3 y_normal = gi::normalize(vec3(0.3, -1, 0.6));
const gi::LightSample y{y_point, y_normal, gi::Color(2, 3, 4), 0.25, 0};

struct Geometry {
  vec3 wi;
  double d2, cos_x, cos_y;
};
Geometry geometry() {
  const vec3 d = y_point - x;
  const vec3 wi = gi::normalize(d);
  return {wi, gi::dot(d, d), gi::dot(n, wi), -gi::dot(y_normal, wi)};
}

}  // namespace

TEST(Ex14_4_NextEvent, DirectionAndDistance) {
  const gi::DirectSample s = gi::next_event_estimate(rho, x, n, wo, y);
  const Geometry g = geometry();
  EXPECT_NEAR(gi::length(s.wi - g.wi), 0.0, 1e-12) << "wi is the unit vector from x towards y";
  EXPECT_NEAR(s.distance, std::sqrt(g.d2), 1e-12) << "distance = |y - x|";
}

TEST(Ex14_4_NextEvent, ConvertsTheAreaDensityToSolidAngle) {
  const gi::DirectSample s = gi::next_event_estimate(rho, x, n, wo, y);
  const Geometry g = geometry();
  ASSERT_GT(g.cos_y, 0) << "the test's light faces x (a fault of the test, not yours)";
  EXPECT_NEAR(s.p_light, y.pdf_area * g.d2 / g.cos_y, 1e-9)
      << "p_light is per steradian: p_A |y - x|^2 / cos(theta_y), with cos(theta_y) = n_y . (x - y) / |x - y| "
         "(the point was drawn per unit area; use area_to_solid_angle)";
}

TEST(Ex14_4_NextEvent, TheEstimateHasBothCosinesAndTheDistance) {
  const gi::DirectSample s = gi::next_event_estimate(rho, x, n, wo, y);
  const Geometry g = geometry();
  const double want = 0.6 / gi::pi * 3 * g.cos_x * g.cos_y / (y.pdf_area * g.d2);
  EXPECT_NEAR(s.estimate.y, want, 1e-9 * want)
      << "estimate = f L_e |cos theta_x| / p_light = (rho / pi) L_e cos(theta_x) cos(theta_y) / (p_A |y - x|^2); "
      << "got " << s.estimate.y << ", which is " << s.estimate.y / want << " times that";
  EXPECT_NEAR(s.estimate.x / s.estimate.z, 2.0 / 4.0, 1e-9) << "per colour channel: times L_e = (2, 3, 4)";
}

TEST(Ex14_4_NextEvent, ALightFacingAwayGivesNothing) {
  gi::LightSample away = y;
  away.normal = -y.normal;
  const gi::DirectSample s = gi::next_event_estimate(rho, x, n, wo, away);
  EXPECT_EQ(s.estimate, gi::Color(0.0)) << "the light shines from its front only: cos(theta_y) <= 0 gives 0";
  EXPECT_EQ(s.p_light, 0.0) << "and no density in that direction (p_light = 0)";
}

TEST(Ex14_4_NextEvent, AveragesToTheFormFactorOfASquareLight) {
  // A square light of side 2 and radiance 2 at height 1.5, centred above the point and
  // facing it: the reflected radiance is rho L F, F = 4 corner-rectangle form factors
  //   F_corner = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
  // A = B = 1 / 1.5. 200 000 light samples, 5 standard errors: a false failure about once
  // in 2 million seeds.
  gi::Scene s;
  gi::Material glow;
  glow.diffuse = gi::Color(0.0);
  glow.emission = gi::Color(2.0);
  s.add(gi::Quad{{-1, 1.5, -1}, {2, 0, 0}, {0, 0, 2}, s.add(glow)});
  const gi::Lights lights = gi::find_lights(s);
  const double A = 1 / 1.5, sa = std::sqrt(1 + A * A);
  const double F = 4 * (2 * A / sa * std::atan(A / sa)) / (2 * gi::pi);
  gi::Rng rng(14);
  std::vector<double> estimates;
  for (int k = 0; k < 2000; ++k) {
    double sum = 0;
    for (int j = 0; j < 100; ++j) {
      const gi::LightSample sample = gi::sample_light(lights, s, x, rng.uniform(), {rng.uniform(), rng.uniform()});
      sum += gi::next_event_estimate(rho, x, n, wo, sample).estimate.x;
    }
    estimates.push_back(sum / 100);
  }
  const gi::testing::Estimate e = gi::testing::estimate(estimates);
  EXPECT_NEAR(e.mean, 0.6 * 2 * F, 5 * e.standard_error)
      << "the direct light from a square light is wrong on average: " << e.mean / (0.6 * 2 * F)
      << " times the closed form";
}
