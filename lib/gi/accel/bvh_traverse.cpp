#include "gi/accel/bvh_traverse.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

// Front to back: of two children whose boxes the ray enters, go on with the one it
// enters first and put the other on a stack, with the distance t_enter at which the
// ray enters it. Every hit shortens the ray (ray.t_max = t), so later primitives
// count only when nearer; a box taken back off the stack is skipped, with all it
// holds, if the ray enters it beyond the nearest hit so far. The first hit found
// need not be the nearest: boxes overlap, and a box entered early can hold a
// surface far away.
//
// [[gnu::flatten]] builds every call made here (slab_test, intersect) into the loop,
// from other files too when the build uses link-time optimisation: a call per box
// would cost about as much as the box test. Without it, GCC stops inlining across
// files once a program has grown by a set fraction, and which calls miss out then
// depends on the whole program.
[[gnu::flatten]] std::optional<Hit> closest_hit(const Bvh& bvh, const Scene& scene, Ray& ray,
                                                TraversalCounts& counts) {
  if (bvh.nodes.empty()) return std::nullopt;
  // BEGIN EXERCISE 5.2 BVH traversal: the nearest hit
  const vec3 inv_dir = 1.0 / ray.direction;
  ++counts.box_tests;
  if (!slab_test(ray, inv_dir, box(bvh.nodes[0]))) return std::nullopt;
  struct Pending {
    std::int32_t node;
    double t_enter;
  };
  Pending stack[bvh_stack_size];
  int size = 0;
  std::optional<Hit> nearest;
  std::int32_t current = 0;
  for (;;) {
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(current)];
    ++counts.nodes_visited;
    std::int32_t next = -1;
    if (node.count > 0) {
      for (std::int32_t i = node.offset; i < node.offset + node.count; ++i) {
        ++counts.primitive_tests;
        if (auto hit = intersect(ray, scene, bvh.refs[static_cast<std::size_t>(i)])) {
          ray.t_max = hit->t;
          nearest = hit;
        }
      }
    } else {
      const std::int32_t left = current + 1, right = node.offset;
      const auto t_left = slab_test(ray, inv_dir, box(bvh.nodes[static_cast<std::size_t>(left)]));
      const auto t_right = slab_test(ray, inv_dir, box(bvh.nodes[static_cast<std::size_t>(right)]));
      counts.box_tests += 2;
      if (t_left && t_right) {
        const bool left_first = *t_left <= *t_right;
        stack[size++] = left_first ? Pending{right, *t_right} : Pending{left, *t_left};
        next = left_first ? left : right;
      } else if (t_left) {
        next = left;
      } else if (t_right) {
        next = right;
      }
    }
    if (next < 0) {  // a leaf, or both boxes missed: back to the nearest box still worth a visit
      while (size > 0 && stack[size - 1].t_enter > ray.t_max * box_reach) --size;  // as far as slab_test reaches
      if (size == 0) return nearest;
      next = stack[--size].node;
    }
    current = next;
  }
  // END EXERCISE 5.2
}

// The same walk, but any hit ends it: there is no nearest hit to look for, so the
// order of the children does not matter and nothing needs skipping.
[[gnu::flatten]] bool any_hit(const Bvh& bvh, const Scene& scene, const Ray& ray, TraversalCounts& counts) {
  if (bvh.nodes.empty()) return false;
  const vec3 inv_dir = 1.0 / ray.direction;
  ++counts.box_tests;
  if (!slab_test(ray, inv_dir, box(bvh.nodes[0]))) return false;
  std::int32_t stack[bvh_stack_size];
  int size = 0;
  std::int32_t current = 0;
  for (;;) {
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(current)];
    ++counts.nodes_visited;
    std::int32_t next = -1;
    if (node.count > 0) {
      for (std::int32_t i = node.offset; i < node.offset + node.count; ++i) {
        ++counts.primitive_tests;
        if (intersect(ray, scene, bvh.refs[static_cast<std::size_t>(i)])) return true;
      }
    } else {
      const std::int32_t left = current + 1, right = node.offset;
      const bool hit_left = slab_test(ray, inv_dir, box(bvh.nodes[static_cast<std::size_t>(left)])).has_value();
      const bool hit_right = slab_test(ray, inv_dir, box(bvh.nodes[static_cast<std::size_t>(right)])).has_value();
      counts.box_tests += 2;
      if (hit_left && hit_right) stack[size++] = right;
      next = hit_left ? left : (hit_right ? right : -1);
    }
    if (next < 0) {
      if (size == 0) return false;
      next = stack[--size];
    }
    current = next;
  }
}

}  // namespace gi
