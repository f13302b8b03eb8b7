// Graded tests of exercise 5.2: BVH traversal, the nearest hit. One point per test.
// Every scene is made of quads, whose intersection is given, so this lab does not
// depend on your lab 1 code. It does use your slab test: do exercise 5.1 first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/core/rng.hpp"
#include "gi/scene/benchmark_scenes.hpp"

using gi::Quad;
using gi::Ray;
using gi::vec3;

namespace {

// A world of the given quads; quad i gets material i, so a hit tells which quad it is.
gi::World world_of(const std::vector<Quad>& quads, const gi::BvhSettings& settings) {
  gi::Scene scene;
  for (std::size_t i = 0; i < quads.size(); ++i) {
    Quad q = quads[i];
    q.material = scene.add(gi::Material{"quad " + std::to_string(i)});
    scene.add(q);
  }
  return gi::make_world(scene, gi::Acceleration::Bvh, settings);
}

// A square of side `size`, centred on the z axis at depth z, facing +z.
Quad square(double z, double size = 2) { return Quad{{-0.5 * size, -0.5 * size, z}, {size, 0, 0}, {0, size, 0}, 0}; }

const gi::BvhSettings one_per_leaf{1, 12, gi::Split::Sah};
const Ray down_the_z_axis{{0, 0, 0}, {0, 0, -1}};

// 1000 squares one behind the other, at z = -1, -2, ..., -1000, one per leaf, and
// rays down and up the stack, each 1.5 from the first square it meets.
gi::World stack_of_squares() {
  std::vector<Quad> quads;
  for (int i = 1; i <= 1000; ++i) quads.push_back(square(-i));
  return world_of(quads, one_per_leaf);
}
const Ray both_ways[] = {{{0, 0, 0.5}, {0, 0, -1}}, {{0, 0, -1001.5}, {0, 0, 1}}};

}  // namespace

TEST(Ex5_2_BvhTraversal, FindsTheQuadInFrontAndMissesWhenNothingIsThere) {
  const gi::World world = world_of({square(-3), square(-7)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, down_the_z_axis);
  ASSERT_TRUE(hit) << "the ray runs down the z axis through two squares";
  EXPECT_NEAR(hit->t, 3.0, 1e-12) << "the square at z = -3 is the nearer one";
  EXPECT_FALSE(gi::closest_hit(world, Ray{{0, 0, 0}, {0, 0, 1}})) << "nothing lies in +z: return std::nullopt";
  EXPECT_FALSE(gi::closest_hit(world, Ray{{5, 0, 0}, {0, 0, -1}})) << "this ray passes beside both squares";
}

TEST(Ex5_2_BvhTraversal, NearestHitWithinALeaf) {
  // Both squares in one leaf (a median split makes no cut below max_leaf_size), in
  // either order.
  const gi::BvhSettings one_leaf{4, 12, gi::Split::Median};
  const auto far_first = gi::closest_hit(world_of({square(-8), square(-3)}, one_leaf), down_the_z_axis);
  ASSERT_TRUE(far_first);
  EXPECT_NEAR(far_first->t, 3.0, 1e-12) << "the leaf lists the square at t = 8 first and the one at t = 3 second: "
                                           "the first hit found is not the nearest; test every primitive of a leaf";
  EXPECT_EQ(far_first->material, 1) << "the Hit returned must be the nearest quad's";
  const auto near_first = gi::closest_hit(world_of({square(-3), square(-8)}, one_leaf), down_the_z_axis);
  ASSERT_TRUE(near_first);
  EXPECT_NEAR(near_first->t, 3.0, 1e-12) << "a later, farther hit replaced the nearer one: after each hit set "
                                            "ray.t_max = hit->t, so that only nearer hits are found afterwards";
}

TEST(Ex5_2_BvhTraversal, NearestHitAcrossOverlappingBoxes) {
  // A long slanted quad whose box reaches from z = -1 to z = -20, hit at t = 10.5,
  // and a small square at z = -5 inside that box's extent.
  const Quad slanted{{-1, -1, -1}, {2, 0, 0}, {0, 2, -19}, 0};
  const gi::World world = world_of({slanted, square(-5, 1)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, down_the_z_axis);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 5.0, 1e-12)
      << "the ray enters the slanted quad's box first (t = 1), and finds that quad at t = 10.5; but the other "
         "box, entered at t = 5 < 10.5, holds a nearer square. Boxes overlap: after a hit keep visiting every "
         "box the ray enters before the nearest hit so far";
}

TEST(Ex5_2_BvhTraversal, VisitsTheFartherBoxWhenTheNearerHoldsNoHit) {
  // A thin diagonal strip at z = -2: its box spans [-1, 1.1] x [-1.1, 1], but the
  // strip itself stays near the line x = y. Behind it, a large square at z = -6.
  const Quad strip{{-1, -1, -2}, {2, 2, 0}, {0.1, -0.1, 0}, 0};
  const gi::World world = world_of({strip, square(-6, 4)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, Ray{{0.5, -0.5, 0}, {0, 0, -1}});
  ASSERT_TRUE(hit) << "the ray enters the strip's box at t = 2 but misses the strip; the square behind, whose box it "
                      "enters at t = 6, must still be visited: keep the farther child on the stack";
  EXPECT_NEAR(hit->t, 6.0, 1e-12);
}

TEST(Ex5_2_BvhTraversal, RespectsTheRaysInterval) {
  const gi::World world = world_of({square(-3), square(-7)}, one_per_leaf);
  EXPECT_FALSE(gi::closest_hit(world, Ray{{0, 0, 0}, {0, 0, -1}, 0, 2.5}))
      << "t_max = 2.5 ends the ray before the first square (t = 3): start from the ray's own t_max";
  const auto hit = gi::closest_hit(world, Ray{{0, 0, 0}, {0, 0, -1}, 4, 100});
  ASSERT_TRUE(hit) << "with t_min = 4 the ray starts past the first square and hits the second";
  EXPECT_NEAR(hit->t, 7.0, 1e-12);
}

TEST(Ex5_2_BvhTraversal, CountsItsWork) {
  // Two squares side by side, one leaf each; the ray hits the left one only.
  const gi::World world = world_of({Quad{{-3, -1, -4}, {2, 0, 0}, {0, 2, 0}, 0},
                                    Quad{{1, -1, -4}, {2, 0, 0}, {0, 2, 0}, 0}}, one_per_leaf);
  gi::TraversalCounts counts;
  ASSERT_TRUE(gi::closest_hit(world, Ray{{-2, 0, 0}, {0, 0, -1}}, &counts));
  EXPECT_GE(counts.box_tests, 2u) << "count every slab test in counts.box_tests (the root and its two children)";
  EXPECT_GE(counts.nodes_visited, 2u) << "count every node you look into in counts.nodes_visited (the root and the "
                                         "leaf that was hit)";
  EXPECT_LE(counts.nodes_visited, 3u) << "only the root and the one leaf whose box the ray enters need a visit";
  EXPECT_EQ(counts.primitive_tests, 1u) << "count every intersect() call in counts.primitive_tests; the right "
                                           "square's box is missed, so only the left square is tested";
}

TEST(Ex5_2_BvhTraversal, ShrinkingTMaxSkipsEverythingBehindTheHit) {
  // Down the stack and up it: a traversal that always takes the same child first
  // goes the right way round at least once.
  const gi::World world = stack_of_squares();
  std::uint64_t fewest = 1000;
  for (const Ray& ray : both_ways) {
    gi::TraversalCounts counts;
    const auto hit = gi::closest_hit(world, ray, &counts);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.5, 1e-12);
    ASSERT_GT(counts.primitive_tests, 0u) << "count primitive tests in counts.primitive_tests";
    fewest = std::min(fewest, counts.primitive_tests);
  }
  EXPECT_LE(fewest, 4u) << "1000 squares one behind the other, and the traversal tested " << fewest << " of them. "
                        << "Once the first is hit at t = 1.5, every other box is entered beyond it and must be "
                        << "skipped unopened: set ray.t_max = hit->t at each hit, and skip a box taken off the "
                        << "stack if the ray enters it beyond ray.t_max";
}

TEST(Ex5_2_BvhTraversal, VisitsTheNearerChildFirst) {
  const gi::World world = stack_of_squares();
  for (const Ray& ray : both_ways) {
    gi::TraversalCounts counts;
    const auto hit = gi::closest_hit(world, ray, &counts);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.5, 1e-12);
    ASSERT_GT(counts.primitive_tests, 0u) << "count primitive tests in counts.primitive_tests";
    EXPECT_LE(counts.primitive_tests, 4u)
        << "going " << (ray.direction.z < 0 ? "down" : "up") << " the stack of 1000 squares the traversal tested "
        << counts.primitive_tests << " of them. Of two children whose boxes the ray enters, visit first the one "
        << "it enters first (the smaller t_enter), whichever is left or right; the other way round the squares "
        << "are found back to front, each nearer than the last";
  }
}

TEST(Ex5_2_BvhTraversal, AgreesWithBruteForceOnRandomRays) {
  const gi::Scene room = gi::quad_room(1500);
  const gi::World brute = gi::make_world(room, gi::Acceleration::BruteForce);
  const gi::World bvh = gi::make_world(room, gi::Acceleration::Bvh);
  gi::Rng rng(2024);
  for (int i = 0; i < 2000; ++i) {
    const double z = 2 * rng.uniform() - 1, phi = 2 * gi::pi * rng.uniform(), s = std::sqrt(1 - z * z);
    const Ray ray{{9.6 * rng.uniform() - 4.8, 0.1 + 3.3 * rng.uniform(), 9.6 * rng.uniform() - 4.8},
                  {s * std::cos(phi), s * std::sin(phi), z}};
    const auto expected = gi::closest_hit(brute, ray);
    const auto hit = gi::closest_hit(bvh, ray);
    ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i << " from the inside of a closed room must hit";
    ASSERT_NEAR(hit->t, expected->t, 1e-9 * expected->t)
        << "ray " << i << ": the BVH found a hit at t = " << hit->t << ", testing every quad finds t = "
        << expected->t << (hit->t > expected->t ? ": not the nearest" : ": nearer than any quad?");
  }
}
