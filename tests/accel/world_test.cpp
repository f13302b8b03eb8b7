#include "gi/accel/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "gi/core/rng.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"

using gi::Acceleration;
using gi::Ray;
using gi::vec3;

namespace {

const Acceleration all[] = {Acceleration::BruteForce, Acceleration::BoundingBoxes, Acceleration::Bvh,
                            Acceleration::FastBvh};

vec3 random_direction(gi::Rng& rng) {
  const double z = 2 * rng.uniform() - 1, phi = 2 * gi::pi * rng.uniform(), s = std::sqrt(1 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// Rays from random points in [lo, hi] in random directions; some with a finite
// t_max (shadow rays) and some starting a little way along (t_min > 0).
std::vector<Ray> random_rays(const vec3& lo, const vec3& hi, int count, std::uint64_t seed) {
  gi::Rng rng(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray ray{lo + (hi - lo) * vec3(rng.uniform(), rng.uniform(), rng.uniform()), random_direction(rng)};
    if (i % 3 == 1) ray.t_max = 3 * rng.uniform();
    if (i % 5 == 2) ray.t_min = 0.5 * rng.uniform();
    rays.push_back(ray);
  }
  return rays;
}

// Every method finds the same nearest hit (t, material, point) and the same any-hit
// answer as brute force. Exact ties between primitives may pick either, so t is
// compared to a few ulps; the material must match.
void expect_agreement(const gi::Scene& scene, const std::vector<Ray>& rays) {
  const gi::World brute = gi::make_world(scene, Acceleration::BruteForce);
  const gi::World boxes = gi::make_world(scene, Acceleration::BoundingBoxes);
  const gi::World bvh = gi::make_world(scene, Acceleration::Bvh);
  const gi::World bvh_median = gi::make_world(scene, Acceleration::Bvh, {1, 12, gi::Split::Median});
  const gi::World fast = gi::make_world(scene, Acceleration::FastBvh);
  const gi::World fast_median = gi::make_world(scene, Acceleration::FastBvh, {1, 12, gi::Split::Median});
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto expected = gi::closest_hit(brute, rays[i]);
    const bool expected_any = gi::any_hit(brute, rays[i]);
    ASSERT_EQ(expected_any, expected.has_value()) << "ray " << i;
    hits += expected.has_value();
    for (const gi::World* world : {&boxes, &bvh, &bvh_median, &fast, &fast_median}) {
      const auto hit = gi::closest_hit(*world, rays[i]);
      ASSERT_EQ(hit.has_value(), expected.has_value()) << gi::name(world->acceleration) << ", ray " << i;
      EXPECT_EQ(gi::any_hit(*world, rays[i]), expected_any) << gi::name(world->acceleration) << ", ray " << i;
      if (!hit) continue;
      EXPECT_NEAR(hit->t, expected->t, 1e-12 * expected->t) << gi::name(world->acceleration) << ", ray " << i;
      EXPECT_EQ(hit->material, expected->material) << gi::name(world->acceleration) << ", ray " << i;
      EXPECT_LT(gi::length(hit->point - expected->point), 1e-9) << gi::name(world->acceleration) << ", ray " << i;
    }
  }
  EXPECT_GT(hits, static_cast<int>(rays.size()) / 10);  // the rays do hit things
}

}  // namespace

TEST(World, BruteForceFindsTheNearestOfAllPrimitiveKinds) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Sphere{{0, 0, -10}, 1, m});
  scene.add(gi::Quad{{-1, -1, -5}, {2, 0, 0}, {0, 2, 0}, m});
  scene.add(gi::Plane{{0, 0, -20}, {0, 0, 1}, m});
  const gi::World world = gi::make_world(scene, Acceleration::BruteForce);
  const auto hit = gi::closest_hit(world, gi::Ray{{0, 0, 0}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 5.0);  // the quad, though it was added after the sphere
  EXPECT_TRUE(gi::any_hit(world, gi::Ray{{0, 0, 0}, {0, 0, -1}, 0, 6}));
  EXPECT_FALSE(gi::any_hit(world, gi::Ray{{0, 0, 0}, {0, 0, -1}, 0, 4.9}));
  EXPECT_FALSE(gi::closest_hit(world, gi::Ray{{0, 0, 0}, {0, 0, 1}}));
}

TEST(World, NamesRoundTripAndUnknownNamesListTheKnownOnes) {
  for (const Acceleration a : all) EXPECT_EQ(gi::acceleration_from_name(gi::name(a)), a);
  EXPECT_EQ(gi::acceleration_names(), (std::vector<std::string>{"brute-force", "bounding-boxes", "bvh", "bvh-fast"}));
  try {
    gi::acceleration_from_name("kd-tree");
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bounding-boxes"), std::string::npos) << e.what();
  }
}

TEST(World, AllMethodsAgreeOnRandomSpheres) {
  const gi::Scene scene = gi::random_spheres(2000, 5);
  expect_agreement(scene, random_rays(vec3(-6), vec3(6), 3000, 1));
  std::vector<Ray> camera;  // and coherent rays from outside, as the camera sees them
  const gi::CameraFrame frame = gi::camera_frame(scene.camera, 40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) camera.push_back(gi::primary_ray(frame, x + 0.5, y + 0.5));
  expect_agreement(scene, camera);
}

TEST(World, AllMethodsAgreeInTheQuadRoom) {
  expect_agreement(gi::quad_room(3000), random_rays({-4.9, 0.1, -4.9}, {4.9, 3.4, 4.9}, 4000, 2));
}

TEST(World, AllMethodsAgreeWithPlanesAndMixedPrimitives) {
  gi::Scene scene = gi::make_scene("s10");  // a plane and spheres
  for (const gi::Quad& q : gi::quad_room(200).quads) scene.add(gi::Quad{q.corner, q.edge_u, q.edge_v, 0});
  expect_agreement(scene, random_rays({-6, 0.1, -6}, {6, 4, 8}, 3000, 3));
}

TEST(World, TrianglesAgreeAndHitsNameTheirPrimitive) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  gi::Rng rng(9);
  for (int i = 0; i < 500; ++i) {
    const vec3 a = vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 10.0 - 5.0;
    scene.add(gi::Triangle{a, a + random_direction(rng), a + random_direction(rng), m});
  }
  const std::vector<Ray> rays = random_rays(vec3(-6), vec3(6), 3000, 4);
  expect_agreement(scene, rays);
  const gi::World brute = gi::make_world(scene, Acceleration::BruteForce), bvh = gi::make_world(scene);
  int hits = 0;
  for (const Ray& ray : rays) {
    const auto a = gi::closest_hit(brute, ray), b = gi::closest_hit(bvh, ray);
    if (!a) continue;
    ++hits;
    ASSERT_TRUE(b);
    EXPECT_EQ(a->object, b->object);
    ASSERT_GE(a->object, 0);
    EXPECT_TRUE(gi::intersect(ray, scene.triangles[static_cast<std::size_t>(a->object)])) << "object names the hit";
  }
  EXPECT_GT(hits, 100);
}

TEST(World, CountsShowTheTreeTestsFarFewerThanAll) {
  const int n = 10000;
  const std::vector<Ray> rays = random_rays(vec3(-5), vec3(5), 1000, 4);
  gi::TraversalCounts brute, boxes, tree;
  const gi::Scene scene = gi::random_spheres(n, 6);
  const gi::World brute_world = gi::make_world(scene, Acceleration::BruteForce);
  const gi::World boxes_world = gi::make_world(scene, Acceleration::BoundingBoxes);
  const gi::World tree_world = gi::make_world(scene, Acceleration::Bvh);
  for (const Ray& ray : rays) {
    gi::closest_hit(brute_world, ray, &brute);
    gi::closest_hit(boxes_world, ray, &boxes);
    gi::closest_hit(tree_world, ray, &tree);
  }
  const double per_ray = 1.0 / static_cast<double>(rays.size());
  EXPECT_EQ(brute.primitive_tests, rays.size() * n);
  EXPECT_EQ(brute.box_tests, 0u);
  EXPECT_EQ(boxes.box_tests, rays.size() * n);
  EXPECT_LT(boxes.primitive_tests, brute.primitive_tests / 100);  // most boxes are missed
  const double tree_tests = per_ray * static_cast<double>(tree.box_tests + tree.primitive_tests);
  EXPECT_LT(tree_tests, 200) << "a BVH over 10 000 spheres should need about 2 log2(N) box tests per ray";
  EXPECT_GT(tree.nodes_visited, rays.size());
}

TEST(World, CountsAddUpAndAnyHitStopsEarly) {
  const gi::World world = gi::make_world(gi::quad_room(1000));
  const Ray ray{{0, 1.5, 0}, {0, 0, -1}};
  gi::TraversalCounts once, twice, any;
  gi::closest_hit(world, ray, &once);
  gi::closest_hit(world, ray, &twice);
  gi::closest_hit(world, ray, &twice);
  EXPECT_GT(once.nodes_visited, 0u);
  EXPECT_EQ(twice.nodes_visited, 2 * once.nodes_visited);
  EXPECT_EQ(twice.box_tests, 2 * once.box_tests);
  EXPECT_EQ(twice.primitive_tests, 2 * once.primitive_tests);
  gi::TraversalCounts sum = once;
  sum += once;
  EXPECT_EQ(sum.primitive_tests, twice.primitive_tests);
  EXPECT_TRUE(gi::any_hit(world, ray, &any));
  EXPECT_GE(any.primitive_tests, 1u);
}

TEST(World, CopiesKeepWorkingAndEmptyWorldsMiss) {
  gi::World copy;
  {
    const gi::World original = gi::make_world(gi::quad_room(500));
    copy = original;  // the tree refers to primitives by index, not address
  }
  const auto hit = gi::closest_hit(copy, Ray{{0, 1.5, 0}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 5.0, 1e-12);  // the back wall, z = -5
  for (const Acceleration a : all) {
    const gi::World empty = gi::make_world(gi::Scene{}, a);
    EXPECT_FALSE(gi::closest_hit(empty, Ray{{0, 0, 0}, {0, 0, -1}}));
    EXPECT_FALSE(gi::any_hit(empty, Ray{{0, 0, 0}, {0, 0, -1}}));
  }
}
