#include <algorithm>
#include <cmath>
#include <limits>

#include "gi/accel/bvh_fast.hpp"

// Lays a built binary tree out for the fast walk (bvh_fast.cpp): four children a node.
namespace gi {

namespace {

constexpr int width = fast_bvh_width;

// Emits the wide node for the plain tree's interior node `plain` and, depth first,
// those below it; returns its index. Its children: the plain node's two, then while
// fewer than four, the interior child with the largest box replaced by its own two
// (a ray is likelier to enter a large box, so opening it saves the most stops).
std::int32_t emit(const Bvh& bvh, std::int32_t plain, FastBvh& fast) {
  const auto node_at = [&](std::int32_t i) -> const BvhNode& { return bvh.nodes[static_cast<std::size_t>(i)]; };
  std::int32_t children[width] = {plain + 1, node_at(plain).offset};
  int n = 2;
  while (n < width) {
    int open = -1;
    double largest = -1;
    for (int c = 0; c < n; ++c) {
      const double area = surface_area(box(node_at(children[c])));
      if (node_at(children[c]).count == 0 && area > largest) open = c, largest = area;
    }
    if (open < 0) break;  // all leaves
    const std::int32_t opened = children[open];
    children[open] = opened + 1;
    children[n++] = node_at(opened).offset;
  }
  const auto at = fast.nodes.size();
  fast.nodes.emplace_back();
  for (int c = 0; c < width; ++c) {
    const bool used = c < n;
    const std::int32_t index = !used ? -1 : node_at(children[c]).count > 0 ? node_at(children[c]).offset
                                                                           : emit(bvh, children[c], fast);
    FastBvhNode& node = fast.nodes[at];  // after emit, which may move fast.nodes
    for (int axis = 0; axis < 3; ++axis) {
      node.bounds[2 * axis][c] = used ? node_at(children[c]).lo[axis] : std::numeric_limits<float>::quiet_NaN();
      node.bounds[2 * axis + 1][c] = used ? node_at(children[c]).hi[axis] : std::numeric_limits<float>::quiet_NaN();
    }
    node.index[c] = index;
    node.count[c] = used ? node_at(children[c]).count : 0;
  }
  return static_cast<std::int32_t>(at);
}

}  // namespace

FastBvh make_fast_bvh(const Bvh& bvh, const Scene& scene) {
  FastBvh fast{{}, bvh.refs, {}, 0};
  if (bvh.nodes.empty()) return fast;
  fast.quads.resize(bvh.refs.size());
  for (std::size_t i = 0; i < bvh.refs.size(); ++i)
    if (bvh.refs[i].kind == PrimitiveKind::Quad) fast.quads[i] = scene.quads[static_cast<std::size_t>(bvh.refs[i].index)];
  for (int axis = 0; axis < 3; ++axis)
    fast.reach = std::max({fast.reach, std::abs(bvh.nodes[0].lo[axis]), std::abs(bvh.nodes[0].hi[axis])});
  if (bvh.nodes[0].count == 0) {
    fast.nodes.reserve(bvh.nodes.size() / 2);
    emit(bvh, 0, fast);
    return fast;
  }
  // The whole tree is one leaf: a root with that leaf as its only child.
  FastBvhNode root{};
  for (int c = 0; c < width; ++c) {
    const bool used = c == 0;
    for (int axis = 0; axis < 3; ++axis) {
      root.bounds[2 * axis][c] = used ? bvh.nodes[0].lo[axis] : std::numeric_limits<float>::quiet_NaN();
      root.bounds[2 * axis + 1][c] = used ? bvh.nodes[0].hi[axis] : std::numeric_limits<float>::quiet_NaN();
    }
    root.index[c] = used ? bvh.nodes[0].offset : -1;
    root.count[c] = used ? bvh.nodes[0].count : 0;
  }
  fast.nodes.push_back(root);
  return fast;
}

}  // namespace gi
