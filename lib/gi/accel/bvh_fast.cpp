#include "gi/accel/bvh_fast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gi/accel/bvh_traverse.hpp"

namespace gi {

namespace {

// Child c of a fast node: its box from the plain tree's node, and what it holds.
void set_child(FastBvhNode& node, int c, const BvhNode& child, std::int32_t index) {
  for (int axis = 0; axis < 3; ++axis) {
    node.bounds[axis][c] = child.lo[axis];
    node.bounds[axis][2 + c] = child.hi[axis];
  }
  node.index[c] = index;
  node.count[c] = child.count;
}

// Emits the fast node for the plain tree's interior node `plain` and, depth first,
// those of its interior descendants; returns its index.
std::int32_t emit(const Bvh& bvh, std::int32_t plain, FastBvh& fast) {
  const auto at = static_cast<std::size_t>(fast.nodes.size());
  fast.nodes.emplace_back();
  const std::int32_t children[2] = {plain + 1, bvh.nodes[static_cast<std::size_t>(plain)].offset};
  for (int c = 0; c < 2; ++c) {
    const BvhNode& child = bvh.nodes[static_cast<std::size_t>(children[c])];
    const std::int32_t index = child.count > 0 ? child.offset : emit(bvh, children[c], fast);
    set_child(fast.nodes[at], c, child, index);  // after emit, which may move fast.nodes
  }
  return static_cast<std::int32_t>(at);
}

// Four floats in one register (GCC's vector extension: SSE on x86-64, NEON on ARM).
// The lanes hold lo and lo, hi and hi of the two children, as the node's rows do.
using float4 = float __attribute__((vector_size(16)));
inline float4 splat(float x) { return float4{x, x, x, x}; }
inline float4 swap_halves(float4 v) { return float4{v[2], v[3], v[0], v[1]}; }
inline float4 min(float4 a, float4 b) { return a < b ? a : b; }
inline float4 max(float4 a, float4 b) { return a > b ? a : b; }
inline float4 abs(float4 v) { return v < 0 ? -v : v; }

// The ray as the float slab test reads it, converted once per ray.
//
// Why the test never misses a box the double test hits. The box corners are floats
// already (exact). The origin's rounding to float moves it by at most 2^-24 |o|: each
// box is widened by pad = 2^-20 (max|o_i| + 1) on every side, which covers it. The
// subtraction, the rounded 1/d and the product add a relative error of at most
// 3 * 2^-24: entry and exit distances are widened by 2^-20 of themselves. A box can
// come out a hair too large, which costs a visit, never a hit. 1/d is kept finite
// (|1/d| <= 2^100, reached only where |d| < 2^-100): inf * 0 would make a NaN where the
// ray runs inside a face's plane, and a distance beyond 2^100 * pad > 10^24 is none.
struct FloatRay {
  float4 origin[3];  // per axis: o + pad, o + pad, o - pad, o - pad (the box widened)
  float4 inv_dir[3];
};
constexpr float slack = 0x1p-20f;

FloatRay float_ray(const Ray& ray) {
  FloatRay r;
  const double largest = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z)});
  const auto pad = static_cast<float>(0x1p-20 * (largest + 1));
  for (int axis = 0; axis < 3; ++axis) {
    const auto o = static_cast<float>(ray.origin[axis]);
    r.origin[axis] = float4{o + pad, o + pad, o - pad, o - pad};
    r.inv_dir[axis] = splat(static_cast<float>(std::clamp(1.0 / ray.direction[axis], -0x1p100, 0x1p100)));
  }
  return r;
}

// Both children's slab tests at once. Lanes 0 and 1 of t_enter tell where the ray
// enters child 0's and child 1's box; hit[c] whether it does within [t_min, t_max].
// Per axis the four distances (lo - o) / d and (hi - o) / d of the two boxes are
// computed together; near and far are their min and max, whichever way the ray runs.
struct TwoSlabs {
  float4 t_enter;
  bool hit[2];
};
inline TwoSlabs slabs(const FastBvhNode& node, const FloatRay& r, float4 t_min, float4 t_max) {
  float4 t_enter = t_min, t_exit = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    float4 bounds;
    __builtin_memcpy(&bounds, node.bounds[axis], sizeof bounds);
    const float4 t = (bounds - r.origin[axis]) * r.inv_dir[axis];  // lo, lo, hi, hi
    const float4 t_swapped = swap_halves(t);                          // hi, hi, lo, lo
    t_enter = max(t_enter, min(t, t_swapped));
    t_exit = min(t_exit, max(t, t_swapped));
  }
  t_enter -= slack * abs(t_enter);
  t_exit += slack * abs(t_exit);
  return {t_enter, {t_enter[0] <= t_exit[0], t_enter[1] <= t_exit[1]}};
}

// A node or a leaf still to visit, and where the ray enters its box.
struct Pending {
  std::int32_t index;
  std::int32_t count;  // 0: the interior node nodes[index]; > 0: a leaf
  float t_enter;
};

Pending child(const FastBvhNode& node, int c, float t_enter) { return {node.index[c], node.count[c], t_enter}; }

}  // namespace

FastBvh make_fast_bvh(const Bvh& bvh) {
  FastBvh fast{{}, bvh.refs};
  if (bvh.nodes.empty()) return fast;
  if (bvh.nodes[0].count == 0) {
    fast.nodes.reserve(bvh.nodes.size() / 2);
    emit(bvh, 0, fast);
    return fast;
  }
  // The whole tree is one leaf: a root with that leaf as both children. Its primitives
  // are tested twice; the second time finds nothing nearer, and nothing new.
  FastBvhNode root{};
  set_child(root, 0, bvh.nodes[0], bvh.nodes[0].offset);
  set_child(root, 1, bvh.nodes[0], bvh.nodes[0].offset);
  fast.nodes.push_back(root);
  return fast;
}

// Front to back, as the plain closest_hit: the nearer child first, the farther one on
// the stack with its entry distance, skipped when a nearer hit has been found by then.
[[gnu::flatten]] std::optional<Hit> closest_hit(const FastBvh& bvh, const Scene& scene, Ray& ray) {
  if (bvh.nodes.empty()) return std::nullopt;
  const FloatRay r = float_ray(ray);
  // The ray's extent in float, converted once per ray and once per hit, not per node.
  const float4 t_min = splat(static_cast<float>(ray.t_min));
  float4 t_max = splat(static_cast<float>(ray.t_max));
  Pending stack[bvh_stack_size];
  int size = 0;
  std::optional<Hit> nearest;
  Pending current{0, 0, 0};
  for (;;) {
    bool descend = false;
    if (current.count > 0) {
      for (std::int32_t i = current.index; i < current.index + current.count; ++i) {
        if (auto hit = intersect(ray, scene, bvh.refs[static_cast<std::size_t>(i)])) {
          ray.t_max = hit->t;
          t_max = splat(static_cast<float>(hit->t));
          nearest = hit;
        }
      }
    } else {
      const FastBvhNode& node = bvh.nodes[static_cast<std::size_t>(current.index)];
      const TwoSlabs s = slabs(node, r, t_min, t_max);
      // Branches, not a computed index: the processor predicts a branch and fetches the
      // next node before the slab test is done; an index computed from the test's
      // result would make every visit wait for it (measured: 1.6x slower).
      descend = true;
      if (s.hit[0] && s.hit[1]) {
        if (s.t_enter[0] <= s.t_enter[1]) {
          stack[size++] = child(node, 1, s.t_enter[1]);
          current = child(node, 0, s.t_enter[0]);
        } else {
          stack[size++] = child(node, 0, s.t_enter[0]);
          current = child(node, 1, s.t_enter[1]);
        }
      } else if (s.hit[0]) {
        current = child(node, 0, s.t_enter[0]);
      } else if (s.hit[1]) {
        current = child(node, 1, s.t_enter[1]);
      } else {
        descend = false;
      }
    }
    if (!descend) {
      while (size > 0 && stack[size - 1].t_enter > ray.t_max) --size;
      if (size == 0) return nearest;
      current = stack[--size];
    }
  }
}

// Any hit ends the walk; the order of the children does not matter.
[[gnu::flatten]] bool any_hit(const FastBvh& bvh, const Scene& scene, const Ray& ray) {
  if (bvh.nodes.empty()) return false;
  const FloatRay r = float_ray(ray);
  const float4 t_min = splat(static_cast<float>(ray.t_min)), t_max = splat(static_cast<float>(ray.t_max));
  Pending stack[bvh_stack_size];
  int size = 0;
  Pending current{0, 0, 0};
  for (;;) {
    bool descend = false;
    if (current.count > 0) {
      for (std::int32_t i = current.index; i < current.index + current.count; ++i)
        if (intersect(ray, scene, bvh.refs[static_cast<std::size_t>(i)])) return true;
    } else {
      const FastBvhNode& node = bvh.nodes[static_cast<std::size_t>(current.index)];
      const TwoSlabs s = slabs(node, r, t_min, t_max);
      descend = true;  // branches, as in closest_hit
      if (s.hit[0]) {
        if (s.hit[1]) stack[size++] = child(node, 1, 0);
        current = child(node, 0, 0);
      } else if (s.hit[1]) {
        current = child(node, 1, 0);
      } else {
        descend = false;
      }
    }
    if (!descend) {
      if (size == 0) return false;
      current = stack[--size];
    }
  }
}

}  // namespace gi
