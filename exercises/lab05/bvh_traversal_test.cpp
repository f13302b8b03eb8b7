// Graded tests of exercise 5.2: BVH traversal, the nearest hit. One point per test.
// Every scene is made of quads, whose intersection is given, so this lab does not
// depend on your lab 1 code. The traversal calls your slab test (exercise 5.1); the
// scenes use tilted squares (boxes with some thickness) and rays along +z where they
// can, so that most slips in 5.1 cost points there only. A test that needs more of
// the slab test checks that first and says so (slab_probe.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/core/rng.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "slab_probe.hpp"
#include "support/print.hpp"

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

// A square of side `size`, centred on the z axis at depth z, tilted a little about
// the y axis so that its box is 0.1 thick: a ray along the z axis meets it at z.
Quad square(double z, double size = 2) {
  return Quad{{-0.5 * size, -0.5 * size, z - 0.05}, {size, 0, 0.1}, {0, size, 0}, 0};
}

const gi::BvhSettings one_per_leaf{1, 12, gi::Split::Sah};
const Ray up_the_z_axis{{0, 0, 0}, {0, 0, 1}};

// 1000 squares one above the other at z = 1, 2, ..., 1000, one per leaf.
gi::World stack_of_squares() {
  std::vector<Quad> quads;
  for (int i = 1; i <= 1000; ++i) quads.push_back(square(i));
  return world_of(quads, one_per_leaf);
}

// A ray from a random point inside quad_room, in a random direction (uniform on the sphere).
Ray ray_in_the_room(gi::Rng& rng) {
  const double z = 2 * rng.uniform() - 1, phi = 2 * gi::pi * rng.uniform(), s = std::sqrt(1 - z * z);
  return Ray{{9.6 * rng.uniform() - 4.8, 0.1 + 3.3 * rng.uniform(), 9.6 * rng.uniform() - 4.8},
             {s * std::cos(phi), s * std::sin(phi), z}};
}

}  // namespace

TEST(Ex5_2_BvhTraversal, FindsTheQuadInFrontAndMissesWhenNothingIsThere) {
  NEEDS_SLAB_TEST(0);
  const gi::World world = world_of({square(3), square(7)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, up_the_z_axis);
  ASSERT_TRUE(hit) << "the ray runs up the z axis through two squares";
  EXPECT_NEAR(hit->t, 3.0, 1e-12) << "the square at z = 3 is the nearer one";
  EXPECT_FALSE(gi::closest_hit(world, Ray{{0, 0, 10}, {0, 0, 1}})) << "nothing lies above z = 10: return std::nullopt";
  EXPECT_FALSE(gi::closest_hit(world, Ray{{5, 0, 0}, {0, 0, 1}})) << "this ray passes beside both squares";
}

TEST(Ex5_2_BvhTraversal, NearestHitWithinALeaf) {
  NEEDS_SLAB_TEST(0);
  // Both squares in one leaf (a median split makes no cut below max_leaf_size), in
  // either order.
  const gi::BvhSettings one_leaf{4, 12, gi::Split::Median};
  const auto far_first = gi::closest_hit(world_of({square(8), square(3)}, one_leaf), up_the_z_axis);
  ASSERT_TRUE(far_first) << "the ray runs up the z axis through two squares in one leaf";
  EXPECT_NEAR(far_first->t, 3.0, 1e-12) << "the leaf lists the square at t = 8 first and the one at t = 3 second: "
                                           "the first hit found is not the nearest; test every primitive of a leaf";
  EXPECT_EQ(far_first->material, 1) << "the Hit returned must be the nearest quad's";
  const auto near_first = gi::closest_hit(world_of({square(3), square(8)}, one_leaf), up_the_z_axis);
  ASSERT_TRUE(near_first) << "the ray runs up the z axis through two squares in one leaf";
  EXPECT_NEAR(near_first->t, 3.0, 1e-12) << "a later, farther hit replaced the nearer one: after each hit set "
                                            "ray.t_max = hit->t, so that only nearer hits are found afterwards";
}

TEST(Ex5_2_BvhTraversal, NearestHitAcrossOverlappingBoxes) {
  NEEDS_SLAB_TEST(0);
  // A long slanted quad whose box reaches from z = 1 to z = 20, hit at t = 10.5, and
  // a small square at z = 5 inside that box's extent.
  const Quad slanted{{-1, -1, 1}, {2, 0, 0}, {0, 2, 19}, 0};
  const gi::World world = world_of({slanted, square(5, 1)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, up_the_z_axis);
  ASSERT_TRUE(hit) << "the ray up the z axis meets both quads";
  EXPECT_NEAR(hit->t, 5.0, 1e-12)
      << "the ray enters the slanted quad's box first (t = 1), and finds that quad at t = 10.5; but the other "
         "box, entered at t = 4.95 < 10.5, holds a nearer square. Boxes overlap: after a hit keep visiting every "
         "box the ray enters before the nearest hit so far";
}

TEST(Ex5_2_BvhTraversal, VisitsTheFartherBoxWhenTheNearerHoldsNoHit) {
  NEEDS_SLAB_TEST(0);
  // A thin diagonal strip at z = 2: its box spans [-1, 1.1] x [-1.1, 1], but the
  // strip itself stays near the line x = y. Above it, a large square at z = 6.
  const Quad strip{{-1, -1, 1.95}, {2, 2, 0.1}, {0.1, -0.1, 0}, 0};
  const gi::World world = world_of({strip, square(6, 4)}, one_per_leaf);
  const auto hit = gi::closest_hit(world, Ray{{0.5, -0.5, 0}, {0, 0, 1}});
  ASSERT_TRUE(hit) << "the ray enters the strip's box at t = 2 but misses the strip; the square beyond, whose box it "
                      "enters at t = 6, must still be visited: keep the farther child on the stack";
  EXPECT_NEAR(hit->t, 6.0125, 1e-12) << "the tilted square is at z = 6.0125 where the ray meets it";
}

TEST(Ex5_2_BvhTraversal, RespectsTheRaysInterval) {
  NEEDS_SLAB_TEST(0);
  const gi::World world = world_of({square(3), square(7)}, one_per_leaf);
  EXPECT_FALSE(gi::closest_hit(world, Ray{{0, 0, 0}, {0, 0, 1}, 0, 2.5}))
      << "t_max = 2.5 ends the ray before the first square (t = 3): start from the ray's own t_max";
  const auto hit = gi::closest_hit(world, Ray{{0, 0, 0}, {0, 0, 1}, 4, 100});
  ASSERT_TRUE(hit) << "with t_min = 4 the ray starts past the first square and hits the second";
  EXPECT_NEAR(hit->t, 7.0, 1e-12) << "the second square is at t = 7";
}

TEST(Ex5_2_BvhTraversal, CountsItsWork) {
  NEEDS_SLAB_TEST(0);
  // Two squares side by side at z = 4, one leaf each; the ray hits the left one only.
  Quad left = square(4), right = square(4);
  left.corner.x -= 2, right.corner.x += 2;
  const gi::World world = world_of({left, right}, one_per_leaf);
  gi::TraversalCounts counts;
  ASSERT_TRUE(gi::closest_hit(world, Ray{{-2, 0, 0}, {0, 0, 1}}, &counts)) << "the ray hits the left square";
  EXPECT_GE(counts.box_tests, 3u) << "count every slab test in counts.box_tests: the root's box and both its "
                                     "children's, three at least";
  EXPECT_GE(counts.nodes_visited, 2u) << "count every node you look into in counts.nodes_visited (the root and the "
                                         "leaf that was hit)";
  EXPECT_LE(counts.nodes_visited, 3u) << "only the root and the one leaf whose box the ray enters need a visit";
  EXPECT_EQ(counts.primitive_tests, 1u) << "count every intersect() call in counts.primitive_tests; the right "
                                           "square's box is missed, so only the left square is tested";
}

TEST(Ex5_2_BvhTraversal, SkipsABoxEnteredBeyondTheNearestHit) {
  NEEDS_SLAB_TEST(1);
  // Two squares, one per leaf, at z = 1 and z = 5: the ray enters both boxes, visits
  // the nearer first and hits its square at t = 1. The other box is entered at 4.95.
  const gi::World world = world_of({square(1), square(5)}, one_per_leaf);
  gi::TraversalCounts counts;
  const auto hit = gi::closest_hit(world, up_the_z_axis, &counts);
  ASSERT_TRUE(hit) << "the ray up the z axis meets both squares";
  EXPECT_NEAR(hit->t, 1.0, 1e-12) << "the nearer square is at t = 1";
  // Which child comes first: going up a stack of 1000 squares, a traversal that takes
  // the farther child first finds them back to front and tests hundreds.
  std::string farther_first;
  if (counts.primitive_tests != 1u || counts.nodes_visited != 2u) {
    gi::TraversalCounts up;
    gi::closest_hit(stack_of_squares(), Ray{{0, 0, -0.5}, {0, 0, 1}}, &up);
    if (up.primitive_tests > 4u)
      farther_first = "going up a stack of 1000 squares the traversal tested " + std::to_string(up.primitive_tests) +
                      " of them: it visits the farther child first and finds the squares back to front, each "
                      "nearer than the last. Of two children whose boxes the ray enters, visit first the one it "
                      "enters first (the smaller t_enter) and push the other; here that is the square at t = 1, "
                      "after which the one at 4.95 is skipped";
  }
  EXPECT_EQ(counts.primitive_tests, 1u)
      << (!farther_first.empty()
              ? farther_first
              : "after the hit at t = 1 the other leaf, whose box the ray enters at t = 4.95 > ray.t_max, holds "
                "nothing nearer: when you take a node off the stack, skip it if the t_enter stored with it is "
                "beyond ray.t_max (store each child with its own t_enter)");
  EXPECT_EQ(counts.nodes_visited, 2u) << (!farther_first.empty()
                                              ? farther_first
                                              : "the root and the nearer leaf: the farther leaf is skipped unopened");
}

TEST(Ex5_2_BvhTraversal, ShrinkingTMaxSkipsEverythingBehindTheHit) {
  NEEDS_SLAB_TEST(1);
  const gi::World world = stack_of_squares();
  gi::TraversalCounts counts;
  const auto hit = gi::closest_hit(world, Ray{{0, 0, -0.5}, {0, 0, 1}}, &counts);
  ASSERT_TRUE(hit) << "the ray up the stack meets all 1000 squares";
  EXPECT_NEAR(hit->t, 1.5, 1e-12) << "the first square is at z = 1, 1.5 from the ray's origin";
  EXPECT_LE(counts.primitive_tests, 2u)
      << "1000 squares one above the other, and the traversal tested " << counts.primitive_tests << " of them. "
      << "Once the first is hit at t = 1.5, every other box is entered beyond it and must be skipped unopened: set "
      << "ray.t_max = hit->t at each hit, and skip a box taken off the stack if the ray enters it beyond ray.t_max";
}

TEST(Ex5_2_BvhTraversal, VisitsTheNearerChildFirst) {
  NEEDS_SLAB_TEST(2);
  // Up the stack and down it: a traversal that always takes the same child first
  // goes the wrong way round in one of them.
  const gi::World world = stack_of_squares();
  for (const Ray& ray : {Ray{{0, 0, -0.5}, {0, 0, 1}}, Ray{{0, 0, 1001.5}, {0, 0, -1}}}) {
    gi::TraversalCounts counts;
    const auto hit = gi::closest_hit(world, ray, &counts);
    ASSERT_TRUE(hit) << "the ray along the stack meets all 1000 squares";
    EXPECT_NEAR(hit->t, 1.5, 1e-12) << "the first square is 1.5 from the ray's origin";
    EXPECT_LE(counts.primitive_tests, 4u)
        << "going " << (ray.direction.z > 0 ? "up" : "down") << " the stack of 1000 squares the traversal tested "
        << counts.primitive_tests << " of them. Of two children whose boxes the ray enters, visit first the one "
        << "it enters first (the smaller t_enter), whichever is left or right; the other way round the squares "
        << "are found back to front, each nearer than the last";
  }
}

TEST(Ex5_2_BvhTraversal, TestsChildrenOnlyUpToTheNearestHit) {
  NEEDS_SLAB_TEST(1);
  const std::string slab_problem = lab05::slab_test_t_max_problem();
  ASSERT_TRUE(slab_problem.empty()) << slab_problem;
  // Three quads, one per leaf. A median split cuts off the one whose centre lies
  // lowest along the longest axis (y): the long ramp, which reaches from y = -20 to
  // y = 1 and from z = 1 to z = 3.1, and meets the z axis at z = 3. The other two
  // share the root's right child: a square at z = 5 and, off to the side at x = 5, a
  // square at z = 2.05, which makes their common box start at z = 2, before the ramp's hit.
  const Quad ramp{{-1, -20, 1}, {2, 0, 0}, {0, 21, 2.1}, 0};
  const Quad beside{{4, -0.5, 2}, {2, 0, 0.1}, {0, 1, 0}, 0};
  const gi::World world = world_of({ramp, square(5, 1), beside}, gi::BvhSettings{1, 12, gi::Split::Median});
  const std::vector<gi::BvhNode>& nodes = world.bvh.nodes;
  ASSERT_TRUE(nodes.size() == 5 && nodes[1].count == 1 && world.bvh.refs[nodes[1].offset].index == 0 &&
              nodes[2].count == 0)
      << "this test's tree is not the one it was written for (root, ramp, then a node over the two squares): "
         "the test itself needs updating, your code is not at fault";
  gi::TraversalCounts counts;
  const auto hit = gi::closest_hit(world, up_the_z_axis, &counts);
  ASSERT_TRUE(hit) << "the ray up the z axis meets the ramp at z = 3";
  EXPECT_NEAR(hit->t, 3.0, 1e-12) << "the ramp is at t = 3; the square at z = 5 is beyond it";
  EXPECT_EQ(counts.primitive_tests, 1u)
      << "after a hit, test children's boxes only up to the nearest hit so far: give slab_test the ray whose "
         "t_max each hit shortened, not a copy taken before the hit. Here the ray hits the ramp at t = 3, then "
         "enters the box of the two squares at t = 2 < 3, so that node is visited; but of its children the ray "
         "enters only the square at z = 5, at t = 4.95, beyond the hit: that leaf must not be opened";
  EXPECT_EQ(counts.nodes_visited, 3u) << "the root, the ramp's leaf and the node over the two squares; both of "
                                         "its children are entered beyond the hit at t = 3, or not at all";
}

TEST(Ex5_2_BvhTraversal, AgreesWithBruteForceOnRandomRays) {
  NEEDS_SLAB_TEST(3);
  const gi::Scene room = gi::quad_room(1500);
  const gi::World brute = gi::make_world(room, gi::Acceleration::BruteForce);
  const gi::World bvh = gi::make_world(room, gi::Acceleration::Bvh);
  gi::Rng rng(2024);
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = ray_in_the_room(rng);
    const auto expected = gi::closest_hit(brute, ray);
    const auto hit = gi::closest_hit(bvh, ray);
    ASSERT_TRUE(expected) << "ray " << i << " starts inside a closed room: testing every quad finds a hit";
    ASSERT_TRUE(hit) << "ray " << i << " from inside a closed room must hit; testing every quad finds t = "
                     << expected->t;
    ASSERT_NEAR(hit->t, expected->t, 1e-9 * expected->t)
        << "ray " << i << ": the BVH found a hit at t = " << hit->t << ", testing every quad finds t = "
        << expected->t << (hit->t > expected->t ? ": not the nearest" : ": nearer than any quad?");
  }
}

TEST(Ex5_2_BvhTraversal, ARayCutAtItsHitKeepsIt) {
  NEEDS_SLAB_TEST(4);
  // Shadow rays to points on the room's walls: each ends exactly at the hit that testing
  // every quad finds, and closest_hit must still return it.
  const gi::Scene room = gi::quad_room(1500);
  const gi::World brute = gi::make_world(room, gi::Acceleration::BruteForce);
  const gi::World bvh = gi::make_world(room, gi::Acceleration::Bvh);
  gi::Rng rng(2025);
  for (int i = 0; i < 4000; ++i) {
    Ray ray = ray_in_the_room(rng);
    const auto expected = gi::closest_hit(brute, ray);
    ASSERT_TRUE(expected) << "ray " << i << " starts inside a closed room: testing every quad finds a hit";
    ray.t_max = expected->t;
    const auto hit = gi::closest_hit(bvh, ray);
    ASSERT_TRUE(hit) << "ray " << i << " ends exactly at its hit, t_max = t = " << ray.t_max
                     << ", and lost it. Your slab test lets in a box the ray enters a hair past t_max (box_reach); "
                        "skip a box taken off the stack only when its t_enter is beyond ray.t_max * box_reach too";
    ASSERT_EQ(hit->t, expected->t) << "ray " << i << ": the same hit, to the bit";
  }
}
