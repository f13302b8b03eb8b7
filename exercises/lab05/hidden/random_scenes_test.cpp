// Hidden graded tests of lab 5 (the autograder's): random boxes and random scenes of
// tilted quads, checked against what testing every primitive finds. One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gi/accel/world.hpp"
#include "gi/core/rng.hpp"
#include "../slab_probe.hpp"
#include "support/print.hpp"
#include "support/random.hpp"

using gi::Ray;
using gi::vec3;

using support::random_vector;

TEST(Ex5_1_RandomBoxes, AgreesWithPointsAlongTheRay) {
  // Whether a ray's segment meets a box, and where it enters, from 20 001 points along
  // the segment: the first inside point lies within one step after the entry.
  gi::Rng rng(505);
  for (int k = 0; k < 300; ++k) {
    const vec3 a = random_vector(rng, 3), b = random_vector(rng, 3);
    const gi::Aabb box{glm::min(a, b), glm::max(a, b)};
    const Ray ray{random_vector(rng, 6), random_vector(rng, 1), 0.5 * rng.uniform(), 2 + 10 * rng.uniform()};
    const int steps = 20000;
    const double step = (ray.t_max - ray.t_min) / steps;
    double first = -1;
    for (int s = 0; s <= steps && first < 0; ++s) {
      const vec3 p = ray.at(ray.t_min + s * step);
      if (p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y && p.z >= box.lo.z && p.z <= box.hi.z)
        first = ray.t_min + s * step;
    }
    const auto t = gi::slab_test(ray, 1.0 / ray.direction, box);
    if (first < 0) {
      if (t) {
        EXPECT_LE(ray.t_max - *t, 2 * step) << "a hit, but the ray's segment stays outside the box (random ray " << k
                                            << ")";
      }
      continue;
    }
    ASSERT_TRUE(t) << "a miss, but the ray's segment passes through the box at t = " << first << " (random ray "
                   << k << ": " << testing::PrintToString(ray) << ", " << testing::PrintToString(box) << ")";
    EXPECT_NEAR(*t, first, step * 1.01) << "return where the segment [t_min, t_max] enters the box (random ray " << k
                                        << ")";
  }
}

TEST(Ex5_2_RandomScenes, AgreesWithBruteForce) {
  NEEDS_SLAB_TEST(3);
  gi::Rng rng(606);
  for (int scene_number = 0; scene_number < 4; ++scene_number) {
    gi::Scene scene;
    const int m = scene.add(gi::Material{});
    for (int q = 0; q < 300; ++q)
      scene.add(gi::Quad{random_vector(rng, 10), random_vector(rng, 1.5), random_vector(rng, 1.5), m});
    const gi::World brute = gi::make_world(scene, gi::Acceleration::BruteForce);
    const gi::World bvh = gi::make_world(scene, gi::Acceleration::Bvh, {1 + scene_number, 12, gi::Split::Sah});
    for (int k = 0; k < 500; ++k) {
      const Ray ray{random_vector(rng, 12), random_vector(rng, 1), 0, 40};
      const auto expected = gi::closest_hit(brute, ray);
      gi::TraversalCounts counts;
      const auto hit = gi::closest_hit(bvh, ray, &counts);
      ASSERT_EQ(hit.has_value(), expected.has_value())
          << (expected ? "no hit, but testing every quad finds one" : "a hit, but testing every quad finds none")
          << " (scene " << scene_number << ", ray " << k << ")";
      if (hit) {
        ASSERT_NEAR(hit->t, expected->t, 1e-9 * (1 + expected->t))
            << "not the nearest hit: testing every quad finds t = " << expected->t << " (scene " << scene_number
            << ", ray " << k << ")";
        EXPECT_EQ(hit->object, expected->object) << "the hit names the wrong quad (scene " << scene_number << ", ray "
                                                 << k << ")";
      }
      ASSERT_LE(counts.primitive_tests, 300u) << "no quad needs testing twice for one ray";
    }
  }
}
