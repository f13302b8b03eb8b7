#include "gi/raytrace/soft_shadows.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gi/raytrace/render.hpp"
#include "gi/raytrace/shading.hpp"
#include "gi/raytrace/whitted.hpp"
#include "gi/scene/soft_shadow_scene.hpp"

using gi::Color;
using gi::vec2;
using gi::vec3;

namespace {

// The fraction of the scene's area light that the floor point (x, 0, 0) sees.
double visible_fraction(const gi::World& world, double x, gi::SoftShadowSettings settings, gi::Rng& rng) {
  const vec3 point(x, 0, 0), up(0, 1, 0);
  const auto reaches = [&](const vec3& y) { return gi::visible(world, point, up, y, 1e-6); };
  const auto one = [](const vec3&) { return Color(1.0); };
  return gi::soft_shadow_estimate(world.scene.area_lights[0], gi::light_samples(settings, rng), reaches, one).x;
}

}  // namespace

TEST(SoftShadows, PointsOnTheLightCoverItUniformly) {
  const gi::QuadLight light{{{1, 2, 3}, {2, 0, 0}, {0.5, 0, 1}, 0}, Color(1)};
  EXPECT_EQ(gi::point_on_light(light, {0, 0}), vec3(1, 2, 3));
  EXPECT_EQ(gi::point_on_light(light, {1, 1}), vec3(3.5, 2, 4));
  EXPECT_EQ(gi::point_on_light(light, {0.5, 0.5}), gi::centre(light.shape));
}

TEST(SoftShadows, PenumbraMatchesSimilarTriangles) {
  // Across the penumbra of the box's edge the visible part of the light grows
  // linearly: at x = x_c + d it is 1/2 + 3d/s (soft_shadow_scene.hpp), for |d| <= s/6.
  const double H = gi::soft_shadow_light_height, h = gi::soft_shadow_box_height;
  const double x_c = gi::soft_shadow_light_x + (gi::soft_shadow_box_edge_x - gi::soft_shadow_light_x) * H / (H - h);
  gi::Rng rng(21);
  for (double s : {0.6, 1.0, 2.0}) {
    const gi::World world = gi::make_world(gi::soft_shadow_scene(s));
    for (double d : {-s / 6 - 0.05, -s / 12, 0.0, s / 12, s / 6 + 0.05}) {
      const double exact = std::clamp(0.5 + 3 * d / s, 0.0, 1.0);
      EXPECT_NEAR(visible_fraction(world, x_c + d, {gi::LightSampling::Jittered, 32}, rng), exact, 0.01)
          << "light " << s << ", d = " << d;
    }
  }
}

TEST(SoftShadows, RandomAndJitteredAreUnbiasedAndJitteredIsLessNoisy) {
  const gi::World world = gi::make_world(gi::soft_shadow_scene(1.0));
  gi::Rng rng(22);
  const double exact = 0.5 + 3 * 0.05;  // x = x_c + 0.05 = 2.38
  const int trials = 3000;
  double mean[2] = {0, 0}, variance[2] = {0, 0};
  for (int k = 0; k < trials; ++k)
    for (int m = 0; m < 2; ++m) {
      const auto sampling = m == 0 ? gi::LightSampling::Random : gi::LightSampling::Jittered;
      const double e = visible_fraction(world, 7.0 / 3 + 0.05, {sampling, 4}, rng) - exact;
      mean[m] += e / trials, variance[m] += e * e / trials;
    }
  for (int m = 0; m < 2; ++m) EXPECT_NEAR(mean[m], 0.0, 4 * std::sqrt(variance[m] / trials)) << m;
  EXPECT_NEAR(variance[0], exact * (1 - exact) / 16, 0.1 * exact * (1 - exact) / 16);  // binomial
  EXPECT_LT(variance[1], 0.3 * variance[0]);
}

TEST(SoftShadows, CentreSamplingIsThePointLightAtTheCentre) {
  gi::TraceSettings settings;
  settings.soft_shadows = {gi::LightSampling::Centre, 1};
  gi::RayCounts counts;
  gi::Rng rng;
  const gi::World area = gi::make_world(gi::soft_shadow_scene(1.0));
  const gi::World point = gi::make_world(gi::soft_shadow_scene(0.0));
  for (double x : {-2.0, 0.5, 1.9, 2.5}) {  // floor points in and out of shadow
    const gi::Ray down{{x, 1.8, 0.9}, gi::normalize(vec3(0.1, -1, -0.5))};
    const Color a = gi::trace(area, down, settings, counts, rng);
    const Color p = gi::trace(point, down, settings, counts, rng);
    // Equal but for the shadow ray starting epsilon = 1e-6 off the surface.
    EXPECT_NEAR(a.x, p.x, 1e-6) << x;
    EXPECT_NEAR(a.z, p.z, 1e-6) << x;
  }
}

TEST(SoftShadows, ShadowRaysPerHitAndSameImageForAnyThreadCount) {
  const gi::World world = gi::make_world(gi::soft_shadow_scene(1.0));
  gi::RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.trace.max_depth = 0;
  settings.trace.soft_shadows = {gi::LightSampling::Random, 3};
  const gi::RenderResult one = gi::render(world, settings, 1, 1);
  // An eye ray that hits a surface casts 9 shadow rays, fewer where part of the light
  // is behind the surface; most of the picture is floor.
  EXPECT_LE(one.counts.of(gi::RayKind::Shadow), 9u * 40 * 30);
  EXPECT_GT(one.counts.of(gi::RayKind::Shadow), 9u * 40 * 30 / 2);
  EXPECT_EQ(gi::render(world, settings, 1, 3).image.pixels, one.image.pixels);
}

TEST(SoftShadows, BadSettingsAreRejected) {
  EXPECT_THROW(gi::check(gi::SoftShadowSettings{gi::LightSampling::Jittered, 0}), std::invalid_argument);
  EXPECT_THROW(gi::light_sampling_from_name("stratified"), std::invalid_argument);
  EXPECT_THROW(gi::soft_shadow_scene(-1), std::invalid_argument);
  EXPECT_THROW(gi::soft_shadow_scene(NAN), std::invalid_argument);
  gi::Scene scene;
  EXPECT_THROW(scene.add(gi::QuadLight{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0}, Color(1)}), std::invalid_argument);
}
