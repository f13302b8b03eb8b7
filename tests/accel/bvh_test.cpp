#include "gi/accel/bvh.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "gi/accel/bvh_traverse.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/sampling.hpp"
#include "gi/scene/benchmark_scenes.hpp"

using gi::Aabb;
using gi::Bvh;
using gi::BvhSettings;
using gi::Split;
using gi::Ray;
using gi::vec3;

namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
         outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

Aabb bounds(const gi::Scene& scene, gi::PrimitiveRef ref) {
  const auto i = static_cast<std::size_t>(ref.index);
  return ref.kind == gi::PrimitiveKind::Quad ? gi::bounds(scene.quads[i]) : gi::bounds(scene.spheres[i]);
}

// Walks the tree from `index` and checks what every tree must satisfy; returns the
// depth of its deepest leaf below `index`.
int check_subtree(const Bvh& bvh, const gi::Scene& scene, int index, const BvhSettings& settings,
                  std::vector<int>& seen_spheres, std::vector<int>& seen_quads) {
  const gi::BvhNode& node = bvh.nodes[static_cast<std::size_t>(index)];
  if (node.count > 0) {
    EXPECT_LE(node.count, settings.max_leaf_size) << "leaf " << index;
    for (int i = node.offset; i < node.offset + node.count; ++i) {
      const gi::PrimitiveRef ref = bvh.refs[static_cast<std::size_t>(i)];
      EXPECT_TRUE(contains(gi::box(node), bounds(scene, ref))) << "leaf " << index << " does not hold its primitive";
      ++(ref.kind == gi::PrimitiveKind::Quad ? seen_quads : seen_spheres)[static_cast<std::size_t>(ref.index)];
    }
    return 0;
  }
  const int left = index + 1, right = node.offset;
  EXPECT_GT(right, left) << "depth first: the right subtree follows the left one";
  EXPECT_LT(right, static_cast<int>(bvh.nodes.size()));
  if (right <= left || right >= static_cast<int>(bvh.nodes.size())) return 0;
  for (const int child : {left, right})
    EXPECT_TRUE(contains(gi::box(node), gi::box(bvh.nodes[static_cast<std::size_t>(child)])))
        << "child " << child << " sticks out of its parent " << index;
  return 1 + std::max(check_subtree(bvh, scene, left, settings, seen_spheres, seen_quads),
                      check_subtree(bvh, scene, right, settings, seen_spheres, seen_quads));
}

void check_tree(const gi::Scene& scene, const BvhSettings& settings) {
  const Bvh bvh = gi::build_bvh(scene, settings);
  ASSERT_FALSE(bvh.nodes.empty());
  std::vector<int> spheres(scene.spheres.size()), quads(scene.quads.size());
  const int depth = check_subtree(bvh, scene, 0, settings, spheres, quads);
  EXPECT_LT(depth, gi::bvh_stack_size);
  for (std::size_t i = 0; i < spheres.size(); ++i) EXPECT_EQ(spheres[i], 1) << "sphere " << i << " in that many leaves";
  for (std::size_t i = 0; i < quads.size(); ++i) EXPECT_EQ(quads[i], 1) << "quad " << i << " in that many leaves";
  EXPECT_EQ(bvh.refs.size(), scene.spheres.size() + scene.quads.size());

  const gi::BvhStats stats = gi::bvh_stats(bvh);
  EXPECT_EQ(stats.nodes, static_cast<int>(bvh.nodes.size()));
  EXPECT_EQ(stats.nodes, 2 * stats.leaves - 1);  // a full binary tree
  EXPECT_EQ(stats.depth, depth);
  EXPECT_LE(stats.largest_leaf, settings.max_leaf_size);
}

// Spheres and quads mixed, in one scene.
gi::Scene mixed_scene() {
  gi::Scene scene = gi::random_spheres(300, 3);
  for (const gi::Quad& q : gi::quad_room(400).quads) scene.add(gi::Quad{q.corner, q.edge_u, q.edge_v, 0});
  return scene;
}

}  // namespace

TEST(Bvh, EveryPrimitiveInExactlyOneLeafAndChildrenInsideParents) {
  for (const Split split : {Split::Sah, Split::Median})
    for (const int leaf : {1, 4, 8}) {
      SCOPED_TRACE("split " + std::to_string(static_cast<int>(split)) + ", max leaf " + std::to_string(leaf));
      const BvhSettings settings{leaf, 12, split};
      check_tree(gi::random_spheres(2000, 1), settings);
      check_tree(gi::quad_room(3000), settings);
      check_tree(mixed_scene(), settings);
    }
}

TEST(Bvh, FewOrManyBinsStillMakeValidTrees) {
  check_tree(gi::quad_room(2000), BvhSettings{4, 2, Split::Sah});
  check_tree(gi::quad_room(2000), BvhSettings{4, 256, Split::Sah});
}

TEST(Bvh, CoincidingPrimitivesAreSplitByCountToKeepLeavesSmall) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  for (int i = 0; i < 1000; ++i) scene.add(gi::Sphere{{1, 2, 3}, 1.0 + 1e-3 * i, m});  // one centre for all
  check_tree(scene, BvhSettings{});
  EXPECT_LE(gi::bvh_stats(gi::build_bvh(scene)).depth, 10);
}

TEST(Bvh, BoxesAreRoundedOutwardsToFloat) {
  // 0.1 has no exact float: a box rounded to nearest could end inside the sphere.
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Sphere{{0.1, 0.1, 0.1}, 0.3, m});
  const Bvh bvh = gi::build_bvh(scene);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_TRUE(contains(gi::box(bvh.nodes[0]), gi::bounds(scene.spheres[0])));
}

TEST(Bvh, BuildIsDeterministic) {
  const gi::Scene scene = gi::quad_room(5000);
  const Bvh a = gi::build_bvh(scene), b = gi::build_bvh(scene);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  ASSERT_EQ(a.refs.size(), b.refs.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].lo, b.nodes[i].lo);
    EXPECT_EQ(a.nodes[i].hi, b.nodes[i].hi);
    EXPECT_EQ(a.nodes[i].offset, b.nodes[i].offset);
    EXPECT_EQ(a.nodes[i].count, b.nodes[i].count);
  }
  for (std::size_t i = 0; i < a.refs.size(); ++i) {
    EXPECT_EQ(a.refs[i].kind, b.refs[i].kind);
    EXPECT_EQ(a.refs[i].index, b.refs[i].index);
  }
}

TEST(Bvh, SahTreeIsCheaperThanMedianTree) {
  const gi::Scene scene = gi::quad_room(5000);
  const double sah = gi::bvh_stats(gi::build_bvh(scene, {4, 12, Split::Sah})).sah_cost;
  const double median = gi::bvh_stats(gi::build_bvh(scene, {4, 12, Split::Median})).sah_cost;
  EXPECT_LT(sah, median);
  EXPECT_LT(sah, 0.01 * 5000);  // and far below testing every quad
}

TEST(Bvh, PlanesStayOutOfTheTree) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Plane{{0, 0, 0}, {0, 1, 0}, m});
  const Bvh bvh = gi::build_bvh(scene);
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.refs.empty());
  EXPECT_EQ(gi::bvh_stats(bvh).nodes, 0);
}

TEST(Bvh, SettingsOutOfRangeAreRejected) {
  const gi::Scene scene = gi::quad_room(100);
  EXPECT_THROW(gi::build_bvh(scene, {0, 12, Split::Sah}), std::invalid_argument);
  EXPECT_THROW(gi::build_bvh(scene, {256, 12, Split::Sah}), std::invalid_argument);
  EXPECT_THROW(gi::build_bvh(scene, {4, 1, Split::Sah}), std::invalid_argument);
  EXPECT_THROW(gi::build_bvh(scene, {4, 257, Split::Sah}), std::invalid_argument);
}

// A ray cut exactly at its hit, as a shadow ray to a point on a surface: both queries
// must still find that hit ([t_min, t_max] is closed). Without box_reach (aabb.hpp)
// the lab walk lost about one in six of these rays in the room of quads.
TEST(Bvh, ARayCutAtItsHitKeepsIt) {
  const gi::Scene room = gi::quad_room(3000);
  const gi::Bvh bvh = gi::build_bvh(room);
  gi::TraversalCounts counts;
  gi::Rng rng(11);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray ray{vec3(-4.8, 0.1, -4.8) + vec3(9.6, 3.3, 9.6) * vec3(rng.uniform(), rng.uniform(), rng.uniform()),
            gi::sample_uniform_sphere({rng.uniform(), rng.uniform()})};
    if (i % 2 == 1) ray.direction[i % 3] = 0, ray.direction = gi::normalize(ray.direction);  // along a wall's plane
    Ray first = ray;
    const auto hit = gi::closest_hit(bvh, room, first, counts);
    if (!hit) continue;
    ++checked;
    ray.t_max = hit->t;
    EXPECT_TRUE(gi::any_hit(bvh, room, ray, counts)) << "ray " << i;
    const auto again = gi::closest_hit(bvh, room, ray, counts);
    ASSERT_TRUE(again) << "ray " << i << " cut at its hit t = " << hit->t << " lost it";
    EXPECT_EQ(again->t, hit->t) << "ray " << i;
  }
  EXPECT_GT(checked, 19000) << "rays from inside the closed room should hit";
}
