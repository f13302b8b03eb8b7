// The two ways of making the binary tree 8-wide (bvh_collapse.hpp). The SAH collapse is
// held to the least cost found by trying every plan there is on small trees (the
// programme's recursion is not used: each plan is priced by sah_cost as a whole), and
// both collapses to the shape rules: every primitive in one leaf, at most eight
// children, leaves no larger than allowed.
#include "gi/accel/bvh_collapse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/scene/benchmark_scenes.hpp"

namespace {

const gi::BvhNode& at(const gi::Bvh& bvh, std::int32_t n) { return bvh.nodes[static_cast<std::size_t>(n)]; }

// The primitives below binary node n: refs[first, first + count).
std::pair<std::int32_t, std::int32_t> span_of(const gi::Bvh& bvh, std::int32_t n) {
  if (at(bvh, n).count > 0) return {at(bvh, n).offset, at(bvh, n).count};
  const auto [first, left] = span_of(bvh, n + 1);
  return {first, left + span_of(bvh, at(bvh, n).offset).second};
}

// Every cut of binary node m's subtree into exactly k parts: m itself (k = 1), or a
// cut of the left child's subtree into j parts beside one of the right's into k - j.
std::vector<std::vector<std::int32_t>> cuts(const gi::Bvh& bvh, std::int32_t m, int k) {
  if (k == 1) return {{m}};
  std::vector<std::vector<std::int32_t>> all;
  if (at(bvh, m).count > 0) return all;
  for (int j = 1; j < k; ++j)
    for (const auto& left : cuts(bvh, m + 1, j))
      for (const auto& right : cuts(bvh, at(bvh, m).offset, k - j)) {
        all.push_back(left);
        all.back().insert(all.back().end(), right.begin(), right.end());
      }
  return all;
}

// Every plan of the tree, one after another, handed to `then`: a wide node's children
// are a cut of its subtree into 2 to 8 parts, and each part is a leaf (a binary leaf,
// or a subtree small enough to merge) or a wide node planned the same way. The plan
// under construction is kept by binary node (children[n] for each n made a wide
// node) and laid out as a WidePlan for pricing.
struct Enumerator {
  const gi::Bvh& bvh;
  int max_leaf_size;
  std::vector<gi::WideNode> children;  // by binary node; a child's index is unused here

  void plan_node(std::int32_t n, const std::function<void()>& then) {
    for (int k = 2; k <= gi::wide_width; ++k)
      for (const auto& cut : cuts(bvh, n, k)) choose(n, cut, 0, then);
  }
  // Gives part i of the cut each of its forms, then goes on to the next part.
  void choose(std::int32_t n, const std::vector<std::int32_t>& cut, std::size_t i, const std::function<void()>& then) {
    if (i == cut.size()) {
      children[static_cast<std::size_t>(n)].size = static_cast<int>(cut.size());
      return then();
    }
    const std::int32_t part = cut[i];
    const auto [first, count] = span_of(bvh, part);
    const bool interior = at(bvh, part).count == 0;
    if (!interior || count <= max_leaf_size) {
      children[static_cast<std::size_t>(n)].child[i] = {part, first, count};
      choose(n, cut, i + 1, then);
    }
    if (interior)
      plan_node(part, [&] {
        children[static_cast<std::size_t>(n)].child[i] = {part, -1, 0};
        choose(n, cut, i + 1, then);
      });
  }
  // The plan as collapse_sah lays one out: depth first from binary node n.
  std::int32_t lay_out(std::int32_t n, gi::WidePlan& plan) const {
    const auto w = static_cast<std::int32_t>(plan.size());
    plan.push_back(children[static_cast<std::size_t>(n)]);
    for (int c = 0; c < plan[static_cast<std::size_t>(w)].size; ++c) {
      const gi::WideChild child = plan[static_cast<std::size_t>(w)].child[static_cast<std::size_t>(c)];
      if (child.count == 0) {
        const std::int32_t below = lay_out(child.node, plan);
        plan[static_cast<std::size_t>(w)].child[static_cast<std::size_t>(c)].index = below;
      }
    }
    return w;
  }
};

// The least SAH cost of any plan of the tree, and how many plans there were.
std::pair<double, long> cheapest_plan(const gi::Bvh& bvh, int max_leaf_size) {
  Enumerator e{bvh, max_leaf_size, std::vector<gi::WideNode>(bvh.nodes.size())};
  double best = std::numeric_limits<double>::infinity();
  long plans = 0;
  e.plan_node(0, [&] {
    ++plans;
    gi::WidePlan plan;
    e.lay_out(0, plan);
    best = std::min(best, gi::sah_cost(bvh, plan));
  });
  return {best, plans};
}

// Checks the shape of a plan: two to eight children a node, each wide node reached
// once and laid out after its parent, each primitive in exactly one leaf, merged
// leaves within max_leaf_size. Returns the number of wide nodes.
int check_plan(const gi::Bvh& bvh, const gi::WidePlan& plan, int max_leaf_size) {
  std::vector<int> seen(bvh.refs.size(), 0), reached(plan.size(), 0);
  std::function<void(std::int32_t, std::int32_t)> walk = [&](std::int32_t w, std::int32_t binary) {
    ++reached[static_cast<std::size_t>(w)];
    const gi::WideNode& node = plan[static_cast<std::size_t>(w)];
    EXPECT_GE(node.size, 2) << "a wide node of one child is a wasted stop";
    EXPECT_LE(node.size, gi::wide_width);
    std::int32_t below = 0;  // the primitives under the node's children
    for (int c = 0; c < node.size; ++c) {
      const gi::WideChild& child = node.child[static_cast<std::size_t>(c)];
      const auto [first, count] = span_of(bvh, child.node);
      below += count;
      if (child.count == 0) {
        EXPECT_GT(child.index, w) << "depth first: a child after its parent";
        walk(child.index, child.node);
        continue;
      }
      EXPECT_EQ(child.index, first);
      EXPECT_EQ(child.count, count);
      if (at(bvh, child.node).count == 0) {
        EXPECT_LE(child.count, max_leaf_size) << "a merged leaf too large";
      }
      for (std::int32_t i = first; i < first + count; ++i) ++seen[static_cast<std::size_t>(i)];
    }
    EXPECT_EQ(below, span_of(bvh, binary).second) << "the children cover their node's subtree";
  };
  walk(0, 0);
  EXPECT_EQ(std::count(reached.begin(), reached.end(), 1), static_cast<long>(plan.size())) << "each wide node once";
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size())) << "each primitive in one leaf";
  return static_cast<int>(plan.size());
}

gi::Bvh tree_of(int quads, int leaf) { return gi::build_bvh(gi::quad_room(quads), {leaf, 12, gi::Split::Sah}); }

// n small quads scattered at random (seeded) in the unit cube, facing every way.
gi::Scene scattered_quads(int n, std::uint64_t seed) {
  gi::Rng rng(seed);
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  for (int i = 0; i < n; ++i) {
    const gi::vec3 corner(rng.uniform(), rng.uniform(), rng.uniform());
    const double size = 0.02 + 0.2 * rng.uniform();
    const int axis = i % 3;
    gi::vec3 u(0), v(0);
    u[(axis + 1) % 3] = size;
    v[(axis + 2) % 3] = size * (0.5 + rng.uniform());
    scene.add(gi::Quad{corner, u, v, m});
  }
  return scene;
}

}  // namespace

TEST(BvhCollapse, TheSahCollapseIsTheCheapestOfEveryPlanOnSmallTrees) {
  // Trees of 5 to 11 leaves, where every plan can be tried (up to some 10^5 of them).
  long most = 0;
  for (int n = 5; n <= 11; ++n)
    for (std::uint64_t seed = 1; seed <= 3; ++seed)
      for (const int leaf : {1, 2}) {
        const gi::Bvh bvh = gi::build_bvh(scattered_quads(n, seed), {leaf, 12, gi::Split::Sah});
        for (const int max_leaf : {1, 2, 3, 4}) {
          const auto [best, plans] = cheapest_plan(bvh, max_leaf);
          most = std::max(most, plans);
          const gi::WidePlan plan = gi::collapse_sah(bvh, max_leaf);
          check_plan(bvh, plan, max_leaf);
          EXPECT_NEAR(gi::sah_cost(bvh, plan), best, 1e-12 * best)
              << n << " quads, seed " << seed << ", leaf " << leaf << ", max leaf " << max_leaf << ": " << plans
              << " plans";
        }
      }
  EXPECT_GT(most, 1000) << "the trees should offer plenty of plans";
}

TEST(BvhCollapse, BothCollapsesKeepEveryPrimitiveOnceInAWellShapedTree) {
  for (const int leaf : {1, 4}) {
    const gi::Bvh bvh = tree_of(3000, leaf);
    std::size_t interior = 0;
    for (const gi::BvhNode& node : bvh.nodes) interior += node.count == 0;
    const int greedy = check_plan(bvh, gi::collapse_largest_first(bvh), leaf);
    // The largest-first rule opens up to seven binary nodes into each wide one, and
    // here, with few leaves among the children, more than three on average.
    EXPECT_LE(3 * static_cast<std::size_t>(greedy), interior) << "leaf " << leaf;
    EXPECT_GE(static_cast<std::size_t>(gi::wide_width - 1) * static_cast<std::size_t>(greedy), interior)
        << "leaf " << leaf;
    for (const int max_leaf : {1, 4, 8}) check_plan(bvh, gi::collapse_sah(bvh, max_leaf), max_leaf);
  }
}

TEST(BvhCollapse, TheSahCollapseCostsLessThanLargestFirst) {
  // On the room of 3 000 quads, cut down to one quad a leaf: the collapse of least cost
  // beats the greedy one on the same boxes (by 2.6%), and may merge leaves, which the
  // greedy one cannot: more choices, never a dearer tree.
  const gi::Bvh bvh = tree_of(3000, 1);
  const double greedy = gi::sah_cost(bvh, gi::collapse_largest_first(bvh));
  const double one = gi::sah_cost(bvh, gi::collapse_sah(bvh, 1));
  const double four = gi::sah_cost(bvh, gi::collapse_sah(bvh, 4));
  EXPECT_LT(one, 0.99 * greedy);
  EXPECT_LE(four, one);
  EXPECT_GT(four, 0.9 * greedy) << "the same boxes: no collapse can be much cheaper";
}

TEST(BvhCollapse, ATreeThatIsOneLeafOrEmptyHasNoWideNodesToPlan) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Quad{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m});
  const gi::Bvh one = gi::build_bvh(scene);
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_TRUE(gi::collapse_sah(one, 4).empty());
  EXPECT_TRUE(gi::collapse_largest_first(one).empty());
  EXPECT_DOUBLE_EQ(gi::sah_cost(one, gi::collapse_sah(one, 4)), gi::wide_node_cost + gi::wide_primitive_cost);
  EXPECT_TRUE(gi::collapse_sah(gi::Bvh{}, 4).empty());
}
