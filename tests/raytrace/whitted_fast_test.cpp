#include "gi/raytrace/whitted_fast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "gi/scene/builtin_scenes.hpp"

namespace {

bool same_bits(const gi::Color& a, const gi::Color& b) {
  const double x[3] = {a.x, a.y, a.z}, y[3] = {b.x, b.y, b.z};
  return std::memcmp(x, y, sizeof x) == 0;
}

// shade_locally_fast against shade_locally at the hits of random rays through the scene:
// the same colour to the bit, the same shadow rays counted, the same numbers drawn
// from the random stream (the next draw of both streams agrees).
void expect_same_local_light(const std::string& scene_name, std::uint64_t seed) {
  const gi::World world = gi::make_world(gi::make_scene(scene_name));
  gi::TraceSettings settings;
  settings.soft_shadows.n = 3;  // 3 x 3 shadow rays per area light
  gi::Rng rays(seed);
  int lit = 0, shaded = 0;
  for (int i = 0; i < 3000; ++i) {
    const gi::Camera& camera = world.scene.camera;
    const double z = 2 * rays.uniform() - 1, phi = 2 * gi::pi * rays.uniform(), s = std::sqrt(1 - z * z);
    const gi::Ray ray{camera.eye, {s * std::cos(phi), s * std::sin(phi), z}};
    const auto hit = gi::closest_hit(world, ray);
    if (!hit) continue;
    const gi::vec3 n = gi::dot(ray.direction, hit->normal) < 0 ? hit->normal : -hit->normal;
    gi::RayCounts plain_counts, fast_counts;
    gi::Rng plain_rng(seed, i), fast_rng(seed, i);
    gi::PixelSample plain_sample = gi::stream_sample(plain_rng), fast_sample = gi::stream_sample(fast_rng);
    const gi::Color plain = gi::shade_locally(world, *hit, n, -ray.direction, settings, plain_counts, plain_sample, 1);
    const gi::Color fast =
        gi::shade_locally_fast(world, *hit, n, -ray.direction, settings, fast_counts, fast_sample, 1);
    EXPECT_TRUE(same_bits(fast, plain)) << scene_name << ", ray " << i;
    EXPECT_EQ(fast_counts.at, plain_counts.at) << scene_name << ", ray " << i;
    EXPECT_EQ(fast_rng.uniform(), plain_rng.uniform()) << scene_name << ", ray " << i;
    ++shaded;
    lit += plain_counts.of(gi::RayKind::Shadow) > 0;
  }
  EXPECT_GT(shaded, 500) << scene_name;  // the rays hit things
  EXPECT_GT(lit, 200) << scene_name;     // and shadow rays were cast from there
}

}  // namespace

TEST(WhittedFast, SameLocalLightAmongPointLights) { expect_same_local_light("s10", 1); }

TEST(WhittedFast, SameLocalLightUnderAnAreaLight) { expect_same_local_light("soft", 2); }
