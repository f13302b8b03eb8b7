#include "gi/accel/world_fast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"

namespace {

// Two hits the same to the bit, field by field (a Hit has padding, so no memcmp of the whole).
bool same_bits(const gi::Hit& a, const gi::Hit& b) {
  const auto bits = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return bits(a.t, b.t) && bits(a.point, b.point) && bits(a.normal, b.normal) && a.material == b.material &&
         a.object == b.object;
}

// closest_hit_fast against closest_hit and any_hit_fast against any_hit on every
// acceleration: the very same hit, the same answer, the same counts, for rays from inside [lo, hi] in random directions, some of them
// shortened (shadow rays) or starting a little way along.
void expect_same_hits(const gi::Scene& scene, const gi::vec3& lo, const gi::vec3& hi, std::uint64_t seed) {
  for (gi::Acceleration acceleration : {gi::Acceleration::BruteForce, gi::Acceleration::BoundingBoxes,
                                        gi::Acceleration::Bvh, gi::Acceleration::FastBvh}) {
    const gi::World world = gi::make_world(scene, acceleration);
    gi::Rng rng(seed);
    int hits = 0;
    int blocked = 0;
    gi::TraversalCounts plain_counts, fast_counts;
    for (int i = 0; i < 2000; ++i) {
      const double z = 2 * rng.uniform() - 1, phi = 2 * gi::pi * rng.uniform(), s = std::sqrt(1 - z * z);
      gi::Ray ray{lo + (hi - lo) * gi::vec3(rng.uniform(), rng.uniform(), rng.uniform()),
                  {s * std::cos(phi), s * std::sin(phi), z}};
      if (i % 3 == 1) ray.t_max = 3 * rng.uniform();
      if (i % 5 == 2) ray.t_min = 0.5 * rng.uniform();
      const auto plain = gi::closest_hit(world, ray, &plain_counts);
      const auto fast = gi::closest_hit_fast(world, ray, &fast_counts);
      ASSERT_EQ(fast.has_value(), plain.has_value()) << gi::name(acceleration) << ", ray " << i;
      const bool any = gi::any_hit(world, ray, &plain_counts);
      EXPECT_EQ(gi::any_hit_fast(world, ray, &fast_counts), any) << gi::name(acceleration) << ", ray " << i;
      blocked += any;
      if (!plain) continue;
      ++hits;
      EXPECT_TRUE(same_bits(*fast, *plain)) << gi::name(acceleration) << ", ray " << i;
    }
    EXPECT_EQ(fast_counts.primitive_tests, plain_counts.primitive_tests) << gi::name(acceleration);
    EXPECT_EQ(fast_counts.box_tests, plain_counts.box_tests) << gi::name(acceleration);
    EXPECT_GT(hits, 200) << gi::name(acceleration);  // the rays do hit things
    EXPECT_GT(blocked, 200) << gi::name(acceleration);
    EXPECT_LT(blocked, 2000) << gi::name(acceleration);  // and some of them miss
  }
}

}  // namespace

TEST(WorldFast, SameHitsAsThePlainQueryAmongSpheresAndAPlane) {
  expect_same_hits(gi::make_scene("s10"), {-6, 0.1, -6}, {6, 4, 8}, 1);
}

TEST(WorldFast, SameHitsAsThePlainQueryInTheQuadRoom) {
  expect_same_hits(gi::quad_room(500), {-4.9, 0.1, -4.9}, {4.9, 3.4, 4.9}, 2);
}
