#include "gi/radiosity/form_factors/shaft.hpp"

#include "gi/geometry/triangle.hpp"

namespace gi {

namespace {

bool overlap(const Aabb& a, const Aabb& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// Has the triangle's plane ends on both sides? Heights within `hair` of it count as
// on either side: a segment from a point on the plane (its own surface) leaves it at
// once, and the test's ray starts 1e-7 of its length away from its ends.
bool crossed(const Triangle& t, const std::vector<vec3>& ends, double hair) {
  const vec3 n = normalize(cross(t.b - t.a, t.c - t.a));
  bool above = false, below = false;
  for (const vec3& p : ends) {
    const double height = dot(p - t.a, n);
    above = above || height > hair, below = below || height < -hair;
  }
  return above && below;
}

}  // namespace

Shaft::Shaft(const FormFactorScene& scene, const std::vector<vec3>& ends) : scene_(&scene) {
  const World& world = scene.world();
  const Bvh& bvh = world.bvh;
  if (bvh.nodes.empty() || ends.empty()) return;
  Aabb box;
  for (const vec3& p : ends) grow(box, p);
  const Aabb whole = gi::box(bvh.nodes[0]);
  const double scale = length(whole.hi - whole.lo) + length(box.hi) + length(box.lo);
  box.lo -= vec3(1e-9 * scale), box.hi += vec3(1e-9 * scale);  // a triangle touching it within round-off counts
  // Down the tree, into every node whose box meets the shaft's (the nodes' float boxes
  // are rounded outwards: never too small). Two pushed and one popped a level: the
  // stack holds at most the tree's depth plus one.
  int stack[bvh_stack_size];
  int pending = 0;
  stack[pending++] = 0;
  while (pending > 0) {
    const int at = stack[--pending];
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(at)];
    if (!overlap(gi::box(node), box)) continue;
    if (node.count == 0) {
      stack[pending++] = node.offset;  // the right child
      stack[pending++] = at + 1;       // the left child, next in the array
      continue;
    }
    for (int i = node.offset; i < node.offset + node.count; ++i) {
      const int k = bvh.refs[static_cast<std::size_t>(i)].index;  // the world holds triangles only
      const Triangle& t = world.scene.triangles[static_cast<std::size_t>(k)];
      if (overlap(bounds(t), box) && crossed(t, ends, 1e-12 * scale)) triangles_.push_back(k);
    }
  }
}

bool Shaft::visible(const vec3& from, const vec3& to) const {
  const std::optional<Ray> segment = segment_between(from, to);
  if (!segment) return true;
  const std::vector<Triangle>& triangles = scene_->world().scene.triangles;
  for (const int k : triangles_)
    if (intersect(*segment, triangles[static_cast<std::size_t>(k)])) return false;
  return true;
}

}  // namespace gi
