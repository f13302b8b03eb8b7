#include "gi/accel/bvh_fast.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "gi/accel/bvh_collapse.hpp"
#include "gi/accel/bvh_traverse.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/simd.hpp"

namespace gi {

namespace {

constexpr int width = wide_width;  // children per node

// Lays the plan's wide nodes out, in its order (depth first, the root first), with
// the boxes the binary tree made.
void lay_out(const Bvh& bvh, const WidePlan& plan, FastBvh& fast) {
  fast.nodes.resize(plan.size());
  for (std::size_t w = 0; w < plan.size(); ++w) {
    FastBvhNode& node = fast.nodes[w];
    for (int c = 0; c < width; ++c) {
      const bool used = c < plan[w].size;
      const WideChild& child = plan[w].child[static_cast<std::size_t>(c)];
      const BvhNode& binary = bvh.nodes[static_cast<std::size_t>(used ? child.node : 0)];
      constexpr float inf = std::numeric_limits<float>::infinity();
      for (int axis = 0; axis < 3; ++axis) {
        node.bounds[2 * axis][c] = used ? binary.lo[axis] : inf;
        node.bounds[2 * axis + 1][c] = used ? binary.hi[axis] : -inf;
      }
      node.index[c] = used ? child.index : -1;
      node.count[c] = used ? child.count : 0;
    }
  }
}

// Four floats in one register (simd.hpp: SSE on x86-64, NEON on ARM64), one lane per
// child. lane_mask reads a group's four verdicts into an int at once: one instruction
// on SSE (movmskps), where the loop over the lanes took 25 (measured with callgrind).
using simd::float4;
using simd::lane_mask;
using simd::load;
using simd::splat;

// The ray as the float slab test reads it, converted once per ray.
//
// Why the test never misses a box the double test hits. The box corners are floats
// already (exact). Every box is widened by pad = 2^-20 (R + max|o_i| + 1) on each
// side, where R is the largest |coordinate| of the tree's root box (FastBvh::reach):
// the near face is moved towards the ray's start (origin_near), the far face away
// (origin_far). The errors it covers, as distances along an axis: the origin rounded
// to float, 2^-24 |o|; the origin plus pad, 2^-24 (|o| + pad); the face minus it,
// 2^-24 (R + |o| + pad); the rounded 1/d and the product, 2^-23 of that difference.
// Together they are under a third of pad (the double test's own rounding is 2^-51 of
// the same sizes), so each face's float crossing lies beyond the exact one on the
// widened side; t_min and t_max are rounded outwards too. A box can come out a hair
// too large, which costs a visit, never a hit. Folding R into pad spares the test a
// widening of every crossing by 2^-20 of itself (16 instructions a visit). 1/d is kept
// finite (|1/d| <= 2^100, reached only where |d| < 2^-100): inf * 0 would make a NaN
// where the ray runs inside a face's plane, and a distance past 2^100 * pad is none.
struct FloatRay {
  float4 origin_near[3], origin_far[3], inv_dir[3];
  int near_row[3];  // the row of the face the ray meets first: lo's, or hi's where d < 0
  int far_row[3];   // the other face's
  float4 t_min;     // the ray's extent, rounded outwards
};

// x in float, rounded down or up where the conversion rounded the other way. The
// neighbouring float is the next bit pattern, towards zero or away from it: the
// library's nextafter is a call, made at half the hits, and the call made the walk
// save its vector registers around it. (f is never -0 where rounded up, nor +0 where
// rounded down: a conversion keeps the sign of x.)
// The bits are copied with std::memcpy, which compiles to one register move as
// std::bit_cast does: the standard libraries of some toolchains still in use
// (Emscripten 3.1's libc++) have no std::bit_cast.
inline std::uint32_t float_bits(float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}
inline float float_of_bits(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
inline float float_down(double x) {
  const auto f = static_cast<float>(x);
  const auto bits = float_bits(f);
  return f > x ? float_of_bits(f > 0 ? bits - 1 : bits + 1) : f;
}
inline float float_up(double x) {
  const auto f = static_cast<float>(x);
  const auto bits = float_bits(f);
  return f < x ? float_of_bits(f < 0 ? bits - 1 : bits + 1) : f;
}

[[maybe_unused]] FloatRay float_ray(const Ray& ray, float reach) {  // unread in a kit, whose walks are hidden
  FloatRay r;
  const double largest = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z)});
  const auto pad = static_cast<float>(0x1p-20 * (reach + largest + 1));
  for (int axis = 0; axis < 3; ++axis) {
    const float inv = static_cast<float>(std::clamp(1.0 / ray.direction[axis], -0x1p100, 0x1p100));
    // Where d < 0 the near face is hi, and the pad goes the other way. Written without
    // branches (signbit, copysign): a random ray's signs are a coin toss each, and a
    // branch on them was mispredicted one and a half times a ray.
    const int backwards = std::signbit(inv);
    const auto o = static_cast<float>(ray.origin[axis]);
    r.near_row[axis] = 2 * axis + backwards;
    r.far_row[axis] = 2 * axis + 1 - backwards;
    r.origin_near[axis] = splat(o + std::copysign(pad, inv));
    r.origin_far[axis] = splat(o - std::copysign(pad, inv));
    r.inv_dir[axis] = splat(inv);
  }
  r.t_min = splat(float_down(ray.t_min));
  return r;
}

// The children's slab tests, four lanes at a time: lane c of group g is child 4g + c.
// t_enter[c] is where the ray enters child c's box, and bit c of hits says whether it
// does within [t_min, t_max]. The groups share no values, so the processor works on
// both at once: a node of eight children takes little longer than one of four.
constexpr int groups = width / 4;
static_assert(width % 4 == 0, "whole groups of four lanes");
struct WideSlabs {
  float t_enter[width];
  unsigned hits;
};
inline WideSlabs slabs(const FastBvhNode& node, const FloatRay& r, float4 t_max) {
  // BEGIN KIT-HIDDEN WITH 5.1 the float slab tests of the fast walk (use --accel bvh)
  WideSlabs out;
  out.hits = 0;
  for (int g = 0; g < groups; ++g) {
    float4 t_enter = r.t_min, t_exit = t_max;
    for (int axis = 0; axis < 3; ++axis) {
      const float4 t_near = (load(node.bounds[r.near_row[axis]] + 4 * g) - r.origin_near[axis]) * r.inv_dir[axis];
      const float4 t_far = (load(node.bounds[r.far_row[axis]] + 4 * g) - r.origin_far[axis]) * r.inv_dir[axis];
      t_enter = t_near > t_enter ? t_near : t_enter;
      t_exit = t_far < t_exit ? t_far : t_exit;
    }
    const auto inside = t_enter <= t_exit;  // lanes of all ones or zeros
    out.hits |= lane_mask(inside) << (4 * g);
    __builtin_memcpy(out.t_enter + 4 * g, &t_enter, sizeof t_enter);
  }
  return out;
  // END KIT-HIDDEN WITH 5.1
}

// A node or a leaf still to visit, and where the ray enters its box.
struct Pending {
  std::int32_t index;
  std::int32_t count;  // 0: the node nodes[index]; > 0: a leaf
  float t_enter;
};

[[maybe_unused]] Pending child(const FastBvhNode& node, int c, float t_enter) { return {node.index[c], node.count[c], t_enter}; }

// The ray against refs[i]: a quad from the copy beside the refs, as the same quad in
// scene.quads gives the same bits; another kind from the scene.
inline std::optional<Hit> intersect(const Ray& ray, const Scene& scene, const FastBvh& bvh, std::int32_t i) {
  const PrimitiveRef ref = bvh.refs[static_cast<std::size_t>(i)];
  if (ref.kind != PrimitiveKind::Quad) return intersect(ray, scene, ref);
  auto hit = intersect(ray, bvh.quads[static_cast<std::size_t>(i)]);
  if (hit) hit->object = ref.index;
  return hit;
}

// Up to width - 1 children wait on the stack per level.
constexpr int fast_stack_size = (width - 1) * bvh_stack_size;

}  // namespace

FastBvh make_fast_bvh(const Bvh& bvh, const Scene& scene, const BvhSettings& settings) {
  FastBvh fast{{}, bvh.refs, {}, 0};
  if (bvh.nodes.empty()) return fast;
  fast.quads.resize(bvh.refs.size());
  for (std::size_t i = 0; i < bvh.refs.size(); ++i)
    if (bvh.refs[i].kind == PrimitiveKind::Quad) fast.quads[i] = scene.quads[static_cast<std::size_t>(bvh.refs[i].index)];
  for (int axis = 0; axis < 3; ++axis)
    fast.reach = std::max({fast.reach, std::abs(bvh.nodes[0].lo[axis]), std::abs(bvh.nodes[0].hi[axis])});
  WidePlan plan;
  if (bvh.nodes[0].count > 0) {  // the whole tree is one leaf: a root with that leaf as its only child
    plan.emplace_back();
    plan[0].child[0] = {0, bvh.nodes[0].offset, bvh.nodes[0].count};
    plan[0].size = 1;
  } else {
    plan = settings.collapse == WideCollapse::Sah ? collapse_sah(bvh, settings.max_leaf_size)
                                                  : collapse_largest_first(bvh);
  }
  lay_out(bvh, plan, fast);
  return fast;
}

// Front to back, as the plain closest_hit: of the children the ray enters, the nearest
// next and the others on the stack, farthest lowest, each with its entry distance, and
// skipped when a nearer hit has been found by the time it comes off.
[[gnu::flatten]] std::optional<Hit> closest_hit(const FastBvh& bvh, const Scene& scene, Ray& ray) {
  // BEGIN KIT-HIDDEN WITH 5.2 the fast walk (use --accel bvh)
  if (bvh.nodes.empty()) return std::nullopt;
  const FloatRay r = float_ray(ray, bvh.reach);
  float4 t_max = splat(float_up(ray.t_max));  // converted once per ray and once per hit, not per node
  Pending stack[fast_stack_size];
  int size = 0;
  std::optional<Hit> nearest;
  Pending current{0, 0, 0};
  for (;;) {
    if (current.count > 0) {
      for (std::int32_t i = current.index; i < current.index + current.count; ++i) {
        if (auto hit = intersect(ray, scene, bvh, i)) {
          ray.t_max = hit->t;
          t_max = splat(float_up(hit->t));
          nearest = hit;
        }
      }
    } else {
      const FastBvhNode& node = bvh.nodes[static_cast<std::size_t>(current.index)];
      const WideSlabs s = slabs(node, r, t_max);
      // Branches on the hit mask rather than indices computed from the test: the
      // processor predicts a branch and fetches the next node before the test is done
      // (an index computed from its result made every visit wait for it: 1.3-1.7x
      // slower, docs/05).
      unsigned hits = s.hits;
      if (hits != 0) {
        int c = std::countr_zero(hits);  // the first child entered
        hits &= hits - 1;
        if (hits == 0) {  // the only one: straight on, past the stack
          current = child(node, c, s.t_enter[c]);
          continue;
        }
        // Several: the nearest goes on at once, the others onto the stack in order of
        // entry, the farthest lowest (insertion slides those entered no later up by
        // one). On a tie the child with the lower index goes first, as the plain walk's
        // left child does.
        int nearest_child = c;
        const int first = size;
        do {
          int k = std::countr_zero(hits);
          hits &= hits - 1;
          if (s.t_enter[k] < s.t_enter[nearest_child]) std::swap(k, nearest_child);
          int at = size++;
          while (at > first && stack[at - 1].t_enter <= s.t_enter[k]) {
            stack[at] = stack[at - 1];
            --at;
          }
          stack[at] = child(node, k, s.t_enter[k]);
        } while (hits != 0);
        current = child(node, nearest_child, s.t_enter[nearest_child]);
        continue;
      }
    }
    while (size > 0 && stack[size - 1].t_enter > ray.t_max) --size;
    if (size == 0) return nearest;
    current = stack[--size];
  }
  // END KIT-HIDDEN WITH 5.2
}

// Any hit ends the walk; the order of the children does not matter.
[[gnu::flatten]] bool any_hit(const FastBvh& bvh, const Scene& scene, const Ray& ray) {
  // BEGIN KIT-HIDDEN WITH 5.2 the fast walk's any hit (use --accel bvh)
  if (bvh.nodes.empty()) return false;
  const FloatRay r = float_ray(ray, bvh.reach);
  const float4 t_max = splat(float_up(ray.t_max));
  Pending stack[fast_stack_size];
  int size = 0;
  Pending current{0, 0, 0};
  for (;;) {
    if (current.count > 0) {
      for (std::int32_t i = current.index; i < current.index + current.count; ++i)
        if (intersect(ray, scene, bvh, i)) return true;
    } else {
      const FastBvhNode& node = bvh.nodes[static_cast<std::size_t>(current.index)];
      unsigned hits = slabs(node, r, t_max).hits;
      if (hits != 0) {  // on with the first child entered, the others on the stack
        current = child(node, std::countr_zero(hits), 0);
        for (hits &= hits - 1; hits != 0; hits &= hits - 1) stack[size++] = child(node, std::countr_zero(hits), 0);
        continue;
      }
    }
    if (size == 0) return false;
    current = stack[--size];
  }
  // END KIT-HIDDEN WITH 5.2
}

}  // namespace gi
