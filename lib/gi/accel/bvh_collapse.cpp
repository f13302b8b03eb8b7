#include "gi/accel/bvh_collapse.hpp"

#include <algorithm>
#include <limits>

namespace gi {

namespace {

const BvhNode& node_at(const Bvh& bvh, std::int32_t i) { return bvh.nodes[static_cast<std::size_t>(i)]; }
double area(const Bvh& bvh, std::int32_t i) { return surface_area(box(node_at(bvh, i))); }

// The dynamic programme of collapse_sah. For binary node n, cost[i] is the least cost
// of n's subtree hung from a wide node as at most i of its children (i = 1..W, W =
// wide_width):
//
//   a binary leaf:  cost[i] = A(n) C_prim N(n)                 (it cannot be divided)
//   interior:       cost[1] = min( A(n) C_prim N(n)   if N(n) <= max_leaf_size (a leaf),
//                                  A(n) C_wide + cost[W]       (a wide node of its own) )
//                   cost[j] = min over k in 1..j-1 of  cost_left[k] + cost_right[j - k]
//
// cost[j] for j >= 2 gives the subtree as j children: k parts of the left child's
// subtree, j - k of the right's. More parts never cost more (a child's box lies inside
// its parent's, so hanging the parts from the wide node itself only spares the visit
// to a node of their own), so "at most j" is "exactly j" for an interior node. Each
// node is priced once, from its children's costs; only the choices are kept.
using Costs = std::array<double, wide_width + 1>;
struct Choice {
  std::array<std::int8_t, wide_width + 1> left;  // cost[j]'s k
  bool leaf;                                     // cost[1] is the subtree as one leaf
  std::int32_t first, count;                     // the subtree's primitives: refs[first, first + count)
};

struct SahCollapse {
  const Bvh& bvh;
  int max_leaf_size;
  std::vector<Choice> choice;
  WidePlan plan;

  Costs price(std::int32_t n) {
    const BvhNode& node = node_at(bvh, n);
    const double a = area(bvh, n);
    Choice& c = choice[static_cast<std::size_t>(n)];
    Costs cost;
    if (node.count > 0) {
      c.first = node.offset, c.count = node.count, c.leaf = true;
      cost.fill(a * wide_primitive_cost * node.count);
      return cost;
    }
    const std::int32_t l = n + 1, r = node.offset;
    const Costs left = price(l), right = price(r);
    c.first = choice[static_cast<std::size_t>(l)].first;
    c.count = choice[static_cast<std::size_t>(l)].count + choice[static_cast<std::size_t>(r)].count;
    for (int j = 2; j <= wide_width; ++j) {
      cost[j] = std::numeric_limits<double>::infinity();
      for (int k = 1; k < j; ++k)
        if (left[k] + right[j - k] < cost[j]) cost[j] = left[k] + right[j - k], c.left[j] = static_cast<std::int8_t>(k);
    }
    const double as_node = a * wide_node_cost + cost[wide_width];
    const double as_leaf =
        c.count <= max_leaf_size ? a * wide_primitive_cost * c.count : std::numeric_limits<double>::infinity();
    c.leaf = as_leaf <= as_node;
    cost[1] = std::min(as_leaf, as_node);
    return cost;
  }

  // Reads the choices back. The wide node for binary interior node n: its place in the plan.
  std::int32_t make_node(std::int32_t n) {
    const auto at = static_cast<std::int32_t>(plan.size());
    plan.emplace_back();
    divide(n, wide_width, at);
    return at;
  }
  // n's subtree as j >= 2 children of wide node plan[at].
  void divide(std::int32_t n, int j, std::int32_t at) {
    const int k = choice[static_cast<std::size_t>(n)].left[static_cast<std::size_t>(j)];
    give(n + 1, k, at);
    give(node_at(bvh, n).offset, j - k, at);
  }
  // n's subtree as i children of plan[at] (one, if it is a leaf).
  void give(std::int32_t n, int i, std::int32_t at) {
    const Choice& c = choice[static_cast<std::size_t>(n)];
    if (i > 1 && node_at(bvh, n).count == 0) return divide(n, i, at);
    const WideChild child = c.leaf ? WideChild{n, c.first, c.count} : WideChild{n, make_node(n), 0};
    WideNode& parent = plan[static_cast<std::size_t>(at)];  // after make_node, which may move the plan
    parent.child[static_cast<std::size_t>(parent.size++)] = child;
  }
};

// Plans the wide node of binary interior node n, then those of its children, by the
// largest-first rule; returns its place in the plan.
std::int32_t plan_largest_first(const Bvh& bvh, std::int32_t n, WidePlan& plan) {
  std::int32_t children[wide_width] = {n + 1, node_at(bvh, n).offset};
  int size = 2;
  while (size < wide_width) {
    int open = -1;
    double largest = -1;
    for (int c = 0; c < size; ++c) {
      const double a = area(bvh, children[c]);
      if (node_at(bvh, children[c]).count == 0 && a > largest) open = c, largest = a;
    }
    if (open < 0) break;  // all leaves
    const std::int32_t opened = children[open];
    children[open] = opened + 1;
    children[size++] = node_at(bvh, opened).offset;
  }
  const auto at = static_cast<std::int32_t>(plan.size());
  plan.emplace_back();
  for (int c = 0; c < size; ++c) {
    const BvhNode& child = node_at(bvh, children[c]);
    const WideChild wide = child.count > 0 ? WideChild{children[c], child.offset, child.count}
                                           : WideChild{children[c], plan_largest_first(bvh, children[c], plan), 0};
    plan[static_cast<std::size_t>(at)].child[static_cast<std::size_t>(c)] = wide;
  }
  plan[static_cast<std::size_t>(at)].size = size;
  return at;
}

}  // namespace

double sah_cost(const Bvh& bvh, const WidePlan& plan) {
  if (bvh.nodes.empty()) return 0;
  const double root = area(bvh, 0) > 0 ? area(bvh, 0) : 1.0;
  const BvhNode& top = node_at(bvh, 0);
  if (top.count > 0) return wide_node_cost + wide_primitive_cost * top.count;  // a wide root with one leaf
  double cost = root * wide_node_cost;
  for (const WideNode& node : plan)
    for (int c = 0; c < node.size; ++c) {
      const WideChild& child = node.child[static_cast<std::size_t>(c)];
      cost += area(bvh, child.node) * (child.count > 0 ? wide_primitive_cost * child.count : wide_node_cost);
    }
  return cost / root;
}

WidePlan collapse_largest_first(const Bvh& bvh) {
  WidePlan plan;
  if (!bvh.nodes.empty() && bvh.nodes[0].count == 0) plan_largest_first(bvh, 0, plan);
  return plan;
}

WidePlan collapse_sah(const Bvh& bvh, int max_leaf_size) {
  SahCollapse collapse{bvh, max_leaf_size, std::vector<Choice>(bvh.nodes.size()), {}};
  if (bvh.nodes.empty() || bvh.nodes[0].count > 0) return collapse.plan;
  collapse.price(0);
  collapse.make_node(0);
  return std::move(collapse.plan);
}

}  // namespace gi
