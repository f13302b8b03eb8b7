#include "gi/raytrace/whitted.hpp"

#include <gtest/gtest.h>

using gi::Color;
using gi::vec3;

namespace {

// Two facing mirrors of reflectance k that also glow with emission e. A ray along
// their common normal sees I = e + k I' at every bounce, so with a depth limit D:
//   I = e (1 + k + ... + k^D) = e (1 - k^(D+1)) / (1 - k).
gi::Scene facing_mirrors(double k, double e) {
  gi::Scene scene;
  gi::Material m;
  m.diffuse = Color(0);
  m.mirror = Color(k);
  m.emission = Color(e);
  const int id = scene.add(m);
  scene.add(gi::Plane{{0, 0, -1}, {0, 0, 1}, id});
  scene.add(gi::Plane{{0, 0, 1}, {0, 0, -1}, id});
  return scene;
}

// A clear glass ball (no absorption, no diffuse) under a white sky: every path
// ends in the sky, so with enough depth the ball must vanish: I = 1 (a furnace test).
gi::Scene glass_ball_in_white_sky() {
  gi::Scene scene;
  gi::Material glass;
  glass.diffuse = Color(0);
  glass.transmission = Color(1);
  glass.ior = 1.5;
  scene.add(gi::Sphere{{0, 0, 0}, 1, scene.add(glass)});
  scene.background = Color(1);
  return scene;
}

}  // namespace

TEST(Whitted, FacingMirrorsSumTheGeometricSeries) {
  const gi::World world = gi::make_world(facing_mirrors(0.5, 1.0));
  for (int depth : {0, 1, 2, 5, 20}) {
    gi::TraceSettings settings;
    settings.max_depth = depth;
    gi::RayCounts counts;
    gi::Rng rng;
    const Color c = gi::trace(world, gi::Ray{{0, 0, 0}, {0, 0, 1}}, settings, counts, rng);
    EXPECT_NEAR(c.x, (1 - std::pow(0.5, depth + 1)) / 0.5, 1e-12) << "depth " << depth;
    EXPECT_EQ(counts.of(gi::RayKind::Reflected), static_cast<std::uint64_t>(depth));
    if (depth > 0) {
      EXPECT_EQ(counts.at[int(gi::RayKind::Reflected)][depth], 1u);
    }
  }
}

TEST(Whitted, ContributionThresholdStopsWhenRaysNoLongerMatter) {
  const gi::World world = gi::make_world(facing_mirrors(0.5, 1.0));
  gi::TraceSettings settings;
  settings.max_depth = 60;
  settings.min_contribution = 0.01;  // 0.5^6 = 0.0156 >= 0.01 > 0.5^7
  gi::RayCounts counts;
  gi::Rng rng;
  const Color c = gi::trace(world, gi::Ray{{0, 0, 0}, {0, 0, 1}}, settings, counts, rng);
  EXPECT_EQ(counts.of(gi::RayKind::Reflected), 6u);
  // The error is what the skipped rays would have added: 2 * 0.5^7.
  EXPECT_NEAR(c.x, 2.0 - 2.0 * std::pow(0.5, 7), 1e-12);
}

TEST(Whitted, ClearGlassBallConservesEnergy) {
  const gi::World world = gi::make_world(glass_ball_in_white_sky());
  gi::TraceSettings settings;
  settings.max_depth = 40;
  for (double offset : {0.0, 0.3, 0.7, 0.95}) {
    gi::RayCounts counts;
    gi::Rng rng;
    const Color c = gi::trace(world, gi::Ray{{offset, 0, 5}, {0, 0, -1}}, settings, counts, rng);
    EXPECT_NEAR(c.x, 1.0, 1e-6) << "ray at offset " << offset;
    EXPECT_GT(counts.of(gi::RayKind::Transmitted), 0u);
  }
}

TEST(Whitted, ShallowDepthLosesTheLightTrappedInTheBall) {
  const gi::World world = gi::make_world(glass_ball_in_white_sky());
  gi::TraceSettings settings;
  settings.max_depth = 1;  // enters the ball but cannot leave it
  gi::RayCounts counts;
  gi::Rng rng;
  const Color c = gi::trace(world, gi::Ray{{0, 0, 5}, {0, 0, -1}}, settings, counts, rng);
  EXPECT_NEAR(c.x, 0.04, 1e-12);  // only the Fresnel reflection at normal incidence escapes
}

TEST(Whitted, ShadowedPointGetsOnlyAmbient) {
  gi::Scene scene;
  gi::Material white;
  white.diffuse = Color(1);
  white.ambient = 0.1;
  const int m = scene.add(white);
  scene.add(gi::Plane{{0, 0, 0}, {0, 1, 0}, m});
  scene.add(gi::Sphere{{0, 2, 0}, 0.5, m});
  scene.add(gi::PointLight{{0, 10, 0}, Color(1)});
  scene.ambient_light = Color(1);
  const gi::World world = gi::make_world(scene);
  gi::TraceSettings settings;
  gi::RayCounts counts;
  gi::Rng rng;
  const Color under = gi::trace(world, gi::Ray{{0, 1, 3}, gi::normalize(vec3(0, -1, -3))}, settings, counts, rng);
  EXPECT_NEAR(under.x, 0.1, 1e-12);
  const Color lit = gi::trace(world, gi::Ray{{3, 1, 3}, gi::normalize(vec3(0, -1, -3))}, settings, counts, rng);
  EXPECT_GT(lit.x, 0.9);
}
