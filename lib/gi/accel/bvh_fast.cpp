#include "gi/accel/bvh_fast.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "gi/accel/bvh_traverse.hpp"
#include "gi/core/not_implemented.hpp"

namespace gi {

namespace {

// Four floats in one register (GCC's vector extension: SSE on x86-64, NEON on ARM),
// one lane per child (or per axis, in the ray's set-up).
using float4 = float __attribute__((vector_size(16)));
inline float4 splat(float x) { return float4{x, x, x, x}; }
inline float4 load(const float* row) {
  float4 v;
  __builtin_memcpy(&v, row, sizeof v);
  return v;
}
using int4 = std::int32_t __attribute__((vector_size(16)));

// Bit c set where lane c is all ones: one instruction on SSE (movmskps reads the four
// sign bits), where the loop took 25 (measured with callgrind).
inline unsigned lane_mask(int4 lanes) {
#if defined(__SSE__)
  return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<float4>(lanes)));
#else
  unsigned mask = 0;
  for (int c = 0; c < fast_bvh_width; ++c) mask |= lanes[c] ? 1u << c : 0u;
  return mask;
#endif
}

// The ray as the float slab test reads it, converted once per ray.
//
// Why the test never misses a box the double test hits. The box corners are floats
// already (exact). Every box is widened by pad = 2^-20 (R + max|o_i| + 1) on each
// side, where R is the largest |coordinate| of the tree's root box (FastBvh::reach):
// lo - (o + pad) = (lo - pad) - o and hi - (o - pad) = (hi + pad) - o, so each face is
// moved outwards, whichever way the ray goes. The errors it covers, as distances along
// an axis: the origin rounded to float, 2^-24 |o|; the origin plus pad, 2^-24 (|o| +
// pad); the face minus it, 2^-24 (R + |o| + pad); 1/d, taken in float of d rounded to
// float, 2^-23 of that difference, and the product 2^-24 more. Together they are under
// two fifths of pad
// (the double test's own rounding is 2^-51 of the same sizes), so each face's float
// crossing lies beyond the exact one on the widened side; t_min and t_max are rounded
// outwards too. A box can come out a hair too large, which costs a visit, never a hit.
// Folding R into pad spares the test a widening of every crossing by 2^-20 of itself
// (16 instructions a visit). 1/d is kept finite (|1/d| <= 2^100, reached only where
// |d| < 2^-100, which takes in every d that float rounds to a subnormal or to 0):
// inf * 0 would make a NaN where the ray runs inside a face's plane, and a distance
// past 2^100 * pad is none.
struct FloatRay {
  float4 origin_lo[3];  // o + pad: the lo faces moved outwards by pad
  float4 origin_hi[3];  // o - pad: the hi faces moved outwards by pad
  float4 inv_dir[3];
  float4 t_min;  // the ray's extent, rounded outwards
};

// x in float, rounded down or up where the conversion rounded the other way. The
// neighbouring float is the next bit pattern, towards zero or away from it (f is never
// -0 where rounded up, nor +0 where rounded down: a conversion keeps the sign of x).
// Without branches: whether the conversion rounded up is a coin toss at every hit, and
// the library's nextafter was a call.
inline float float_down(double x) {
  const auto f = static_cast<float>(x);
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t downward = 2u * (bits >> 31) - 1u;  // -1 where f > 0, +1 where f < 0
  return std::bit_cast<float>(bits + static_cast<std::uint32_t>(f > x) * downward);
}
inline float float_up(double x) {
  const auto f = static_cast<float>(x);
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t upward = 1u - 2u * (bits >> 31);  // +1 where f > 0, -1 where f < 0
  return std::bit_cast<float>(bits + static_cast<std::uint32_t>(f < x) * upward);
}

// The three axes at once, in the lanes of one register (the fourth lane idle): one
// division for the three 1/d, and each lane then spread over a register of its own, as
// the slab test reads it. (This set-up took ~100 instructions in double, axis by axis.)
FloatRay float_ray(const Ray& ray, float reach) {
  const double largest = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z)});
  const float4 pad = splat(static_cast<float>(0x1p-20 * (reach + largest + 1)));
  const float4 o = {static_cast<float>(ray.origin.x), static_cast<float>(ray.origin.y),
                    static_cast<float>(ray.origin.z), 0};
  const float4 d = {static_cast<float>(ray.direction.x), static_cast<float>(ray.direction.y),
                    static_cast<float>(ray.direction.z), 1};
  const float4 most = splat(0x1p100f);
  float4 inv = 1 / d;
  inv = inv > most ? most : inv;
  inv = inv < -most ? -most : inv;
  const float4 lo = o + pad, hi = o - pad;
  FloatRay r;
  for (int axis = 0; axis < 3; ++axis) {
    r.origin_lo[axis] = splat(lo[axis]);
    r.origin_hi[axis] = splat(hi[axis]);
    r.inv_dir[axis] = splat(inv[axis]);
  }
  r.t_min = splat(float_down(ray.t_min));
  return r;
}

// The four children's slab tests at once: lane c of t_enter is where the ray enters
// child c's box, and bit c of hits says whether it does within [t_min, t_max].
struct FourSlabs {
  float4 t_enter;
  unsigned hits;
};
inline FourSlabs slabs(const FastBvhNode& node, const FloatRay& r, float4 t_max) {
  // BEGIN KIT-HIDDEN WITH 5.1 the four-wide slab test of the fast walk (use --accel bvh)
  // The near face is whichever of lo and hi the ray crosses first: no swap, no branch on
  // the sign of d. An unused lane's faces are NaN, and the NaN is carried through to
  // t_enter (each comparison below picks its right side when either side is NaN), where
  // `t_enter <= t_exit` fails: no ray enters an unused child, whatever its t_max.
  float4 t_near[3], t_far[3];
  for (int axis = 0; axis < 3; ++axis) {
    const float4 t_lo = (load(node.bounds[2 * axis]) - r.origin_lo[axis]) * r.inv_dir[axis];
    const float4 t_hi = (load(node.bounds[2 * axis + 1]) - r.origin_hi[axis]) * r.inv_dir[axis];
    t_near[axis] = t_hi > t_lo ? t_lo : t_hi;
    t_far[axis] = t_lo > t_hi ? t_lo : t_hi;
  }
  // The axes paired, so that their results meet in two steps, not three.
  const auto later = [](float4 a, float4 b) { return a > b ? a : b; };   // b where either is NaN
  const auto sooner = [](float4 a, float4 b) { return a < b ? a : b; };  // b where either is NaN
  const float4 t_enter = later(later(r.t_min, t_near[0]), later(t_near[1], t_near[2]));
  const float4 t_exit = sooner(sooner(t_max, t_far[0]), sooner(t_far[1], t_far[2]));
  const auto inside = t_enter <= t_exit;  // lanes of all ones or zeros
  return {t_enter, lane_mask(inside)};
  // END KIT-HIDDEN WITH 5.1
}

// A node or a leaf still to visit, and where the ray enters its box.
struct Pending {
  std::int32_t index;
  std::int32_t count;  // 0: the node nodes[index]; > 0: a leaf
  float t_enter;
};

Pending child(const FastBvhNode& node, int c, float t_enter) { return {node.index[c], node.count[c], t_enter}; }

// The leaf refs[first, first + count) against the ray, shortening ray.t_max (and its
// float copy t_max) to each nearer hit. A quad is tested in the copy beside the refs
// (the same quad in scene.quads gives the same bits) by crossing(): only its index is
// kept (nearest_quad), and its Hit is built once, at the end (nearest_hit). Another kind
// is tested in the scene; its Hit is kept (other), and nearest_quad set to -1 to say
// that it is the nearer. The update is a branch, not a choice made without one: the
// next node's slab test reads t_max, and a choice would make it wait for every quad's
// test to finish, where a branch guessed "missed" lets it start at once (written
// without the branch, nearest hits ran 5-10% slower).
inline void test_leaf(const FastBvh& bvh, const Scene& scene, std::int32_t first, std::int32_t count, Ray& ray,
                      float4& t_max, std::int32_t& nearest_quad, std::optional<Hit>& other) {
  for (std::int32_t i = first; i < first + count; ++i) {
    const PrimitiveRef ref = bvh.refs[static_cast<std::size_t>(i)];
    if (ref.kind == PrimitiveKind::Quad) {
      const QuadCrossing x = crossing(ray, bvh.quads[static_cast<std::size_t>(i)]);
      if (x.hit) {
        ray.t_max = x.t;
        t_max = splat(float_up(x.t));
        nearest_quad = i;
      }
    } else if (auto hit = intersect(ray, scene, ref)) {
      ray.t_max = hit->t;
      t_max = splat(float_up(hit->t));
      other = hit;
      nearest_quad = -1;
    }
  }
}

// The walk's answer: the nearest quad's Hit, built from its t (which ray.t_max holds),
// or the other kind's.
inline std::optional<Hit> nearest_hit(const FastBvh& bvh, const Ray& ray, std::int32_t nearest_quad,
                                      const std::optional<Hit>& other) {
  if (nearest_quad < 0) return other;
  Hit hit = hit_at(ray, bvh.quads[static_cast<std::size_t>(nearest_quad)], ray.t_max);
  hit.object = bvh.refs[static_cast<std::size_t>(nearest_quad)].index;
  return hit;
}

// Whether the ray hits refs[i] (a quad: in the copy beside the refs).
inline bool blocks(const FastBvh& bvh, const Scene& scene, std::int32_t i, const Ray& ray) {
  const PrimitiveRef ref = bvh.refs[static_cast<std::size_t>(i)];
  if (ref.kind == PrimitiveKind::Quad) return crossing(ray, bvh.quads[static_cast<std::size_t>(i)]).hit;
  return intersect(ray, scene, ref).has_value();
}

// Up to three children wait on the stack per level.
constexpr int fast_stack_size = (fast_bvh_width - 1) * bvh_stack_size;

}  // namespace

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
  std::int32_t nearest_quad = -1;
  std::optional<Hit> other;
  Pending current{0, 0, 0};
  for (;;) {
    if (current.count > 0) {
      test_leaf(bvh, scene, current.index, current.count, ray, t_max, nearest_quad, other);
    } else {
      const FastBvhNode& node = bvh.nodes[static_cast<std::size_t>(current.index)];
      const FourSlabs s = slabs(node, r, t_max);
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
        // Several: pushed in order of entry, the nearest last, then taken back off
        // below. Insertion slides those entered no later up by one (on a tie the
        // child with the lower index goes first, as the plain walk's left child does).
        const int first = size;
        for (;;) {
          int at = size++;
          while (at > first && stack[at - 1].t_enter <= s.t_enter[c]) {
            stack[at] = stack[at - 1];
            --at;
          }
          stack[at] = child(node, c, s.t_enter[c]);
          if (hits == 0) break;
          c = std::countr_zero(hits);
          hits &= hits - 1;
        }
      }
    }
    while (size > 0 && stack[size - 1].t_enter > ray.t_max) --size;
    if (size == 0) return nearest_hit(bvh, ray, nearest_quad, other);
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
        if (blocks(bvh, scene, i, ray)) return true;
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
