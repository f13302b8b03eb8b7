#include "gi/accel/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace gi {

namespace {

// The surface area heuristic's cost model, in units of one ray-primitive test. A
// visit to an interior node (two slab tests) costs about as much as a quad test; on
// quad_room, ratios from 1:2 to 2:1 made no difference beyond the timing noise.
constexpr double traversal_cost = 1.0;
constexpr double intersection_cost = 1.0;

// Up to this depth the builder cuts where the settings say; deeper, it halves the
// node by count, which ends any tree within 31 more levels and so keeps every leaf
// within reach of the traversal's fixed stack, however lopsided the scene.
constexpr int halving_depth = bvh_stack_size / 2;

// A primitive as the builder sees it.
struct Item {
  Aabb box;
  vec3 centroid;  // of the box: what the builder sorts and bins by
  PrimitiveRef ref;
};

// Cuts the items at the median centroid along the axis where the centroids spread
// most. Returns the number of items put on the left.
std::size_t cut_in_half(std::span<Item> items, const Aabb& centroids) {
  const vec3 extent = centroids.hi - centroids.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::size_t half = items.size() / 2;
  std::nth_element(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(half), items.end(),
                   [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
  return half;
}

// Binned SAH (Wald 2007): on each axis, slice the centroids' extent into equal bins,
// drop every item into its bin, and price the cut at each border between bins with
// one sweep from each end. Returns the number of items put on the left by the
// cheapest cut, or 0 when no cut beats making a leaf (or the centroids coincide).
std::size_t cut_sah(std::span<Item> items, const Aabb& box, const Aabb& centroids, const BvhSettings& settings) {
  struct Bin {
    Aabb box;
    std::size_t count = 0;
  };
  const int bins = settings.bins;
  const auto bin_of = [bins](double c, double lo, double scale) {
    return std::min(bins - 1, static_cast<int>((c - lo) * scale));
  };
  const bool leaf_allowed = items.size() <= static_cast<std::size_t>(settings.max_leaf_size);
  double best_cost = leaf_allowed ? static_cast<double>(items.size()) * intersection_cost
                                  : std::numeric_limits<double>::infinity();
  int best_axis = -1, best_border = 0;
  std::vector<Bin> bin(static_cast<std::size_t>(bins));
  std::vector<double> right_area(bin.size());
  std::vector<std::size_t> right_count(bin.size());
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
    if (!(extent > 0)) continue;
    const double scale = bins / extent;
    std::fill(bin.begin(), bin.end(), Bin{});
    for (const Item& item : items) {
      Bin& b = bin[static_cast<std::size_t>(bin_of(item.centroid[axis], lo, scale))];
      grow(b.box, item.box);
      ++b.count;
    }
    // Border i separates bins [0, i) from [i, bins).
    Aabb side;
    std::size_t n = 0;
    for (std::size_t i = bin.size() - 1; i > 0; --i) {
      grow(side, bin[i].box);
      n += bin[i].count;
      right_area[i] = surface_area(side);
      right_count[i] = n;
    }
    side = Aabb{};
    n = 0;
    for (std::size_t i = 1; i < bin.size(); ++i) {
      grow(side, bin[i - 1].box);
      n += bin[i - 1].count;
      if (n == 0 || right_count[i] == 0) continue;
      const double cost = traversal_cost + intersection_cost *
                                               (surface_area(side) * static_cast<double>(n) +
                                                right_area[i] * static_cast<double>(right_count[i])) /
                                               surface_area(box);
      if (cost < best_cost) best_cost = cost, best_axis = axis, best_border = static_cast<int>(i);
    }
  }
  if (best_axis < 0) return 0;
  const double lo = centroids.lo[best_axis], scale = bins / (centroids.hi[best_axis] - lo);
  const auto middle = std::partition(items.begin(), items.end(), [&](const Item& item) {
    return bin_of(item.centroid[best_axis], lo, scale) < best_border;
  });
  return static_cast<std::size_t>(middle - items.begin());
}

// Stores the box in float, rounded outwards where the conversion rounded inwards,
// so that the node's box holds everything the double box held.
void store_box(BvhNode& node, const Aabb& box) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    node.lo[axis] = static_cast<float>(box.lo[axis]);
    node.hi[axis] = static_cast<float>(box.hi[axis]);
    if (node.lo[axis] > box.lo[axis]) node.lo[axis] = std::nextafter(node.lo[axis], -inf);
    if (node.hi[axis] < box.hi[axis]) node.hi[axis] = std::nextafter(node.hi[axis], inf);
  }
}

struct Builder {
  const BvhSettings& settings;
  std::vector<Item> items;
  Bvh bvh;

  // Emits the subtree over items[begin, end) depth first; returns its root's index.
  std::int32_t build(std::size_t begin, std::size_t end, int depth) {
    const auto index = static_cast<std::int32_t>(bvh.nodes.size());
    bvh.nodes.emplace_back();  // filled in below; indices, not references, survive the children's emplace_back
    const std::span<Item> span(items.data() + begin, end - begin);
    Aabb box, centroids;
    for (const Item& item : span) {
      grow(box, item.box);
      grow(centroids, item.centroid);
    }
    store_box(bvh.nodes[static_cast<std::size_t>(index)], box);

    std::size_t left = 0;  // 0: make a leaf
    if (settings.split == Split::Sah && depth < halving_depth) left = cut_sah(span, box, centroids, settings);
    if (left == 0 && span.size() > static_cast<std::size_t>(settings.max_leaf_size))
      left = cut_in_half(span, centroids);

    if (left == 0) {
      BvhNode& leaf = bvh.nodes[static_cast<std::size_t>(index)];
      leaf.offset = static_cast<std::int32_t>(bvh.refs.size());
      leaf.count = static_cast<std::int32_t>(span.size());
      for (const Item& item : span) bvh.refs.push_back(item.ref);
      return index;
    }
    build(begin, begin + left, depth + 1);  // the left child lands at index + 1
    const std::int32_t right = build(begin + left, end, depth + 1);
    bvh.nodes[static_cast<std::size_t>(index)].offset = right;
    return index;
  }
};

void walk(const Bvh& bvh, std::size_t index, int depth, double root_area, BvhStats& stats) {
  const BvhNode& node = bvh.nodes[index];
  const double p_hit = surface_area(box(node)) / root_area;  // of a random ray that hits the root
  ++stats.nodes;
  if (node.count > 0) {
    ++stats.leaves;
    stats.depth = std::max(stats.depth, depth);
    stats.largest_leaf = std::max(stats.largest_leaf, static_cast<int>(node.count));
    stats.sah_cost += p_hit * node.count * intersection_cost;
    return;
  }
  stats.sah_cost += p_hit * traversal_cost;
  walk(bvh, index + 1, depth + 1, root_area, stats);
  walk(bvh, static_cast<std::size_t>(node.offset), depth + 1, root_area, stats);
}

}  // namespace

Bvh build_bvh(const Scene& scene, const BvhSettings& settings) {
  if (settings.max_leaf_size < 1 || settings.max_leaf_size > 255)
    throw std::invalid_argument("BVH: max_leaf_size must be in 1..255, got " + std::to_string(settings.max_leaf_size));
  if (settings.bins < 2 || settings.bins > 256)
    throw std::invalid_argument("BVH: bins must be in 2..256, got " + std::to_string(settings.bins));
  if (scene.spheres.size() + scene.quads.size() + scene.triangles.size() >
      static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("BVH: more primitives than 32-bit indices can count");

  Builder builder{settings, {}, {}};
  builder.items.reserve(scene.spheres.size() + scene.quads.size() + scene.triangles.size());
  const auto add = [&](const Aabb& box, PrimitiveKind kind, std::size_t index) {
    builder.items.push_back({box, centroid(box), {kind, static_cast<std::int32_t>(index)}});
  };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) add(bounds(scene.spheres[i]), PrimitiveKind::Sphere, i);
  for (std::size_t i = 0; i < scene.quads.size(); ++i) add(bounds(scene.quads[i]), PrimitiveKind::Quad, i);
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) add(bounds(scene.triangles[i]), PrimitiveKind::Triangle, i);
  if (builder.items.empty()) return {};

  builder.bvh.refs.reserve(builder.items.size());
  builder.build(0, builder.items.size(), 0);
  return std::move(builder.bvh);
}

BvhStats bvh_stats(const Bvh& bvh) {
  BvhStats stats;
  if (bvh.nodes.empty()) return stats;
  const double root_area = surface_area(box(bvh.nodes[0]));
  walk(bvh, 0, 0, root_area > 0 ? root_area : 1.0, stats);
  return stats;
}

}  // namespace gi
