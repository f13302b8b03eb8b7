#include "gi/geometry/aabb.hpp"

#include <utility>

#include "gi/core/not_implemented.hpp"

namespace gi {

bool is_empty(const Aabb& box) { return box.lo.x > box.hi.x || box.lo.y > box.hi.y || box.lo.z > box.hi.z; }

void grow(Aabb& box, const vec3& point) {
  box.lo = glm::min(box.lo, point);
  box.hi = glm::max(box.hi, point);
}

void grow(Aabb& box, const Aabb& other) {
  box.lo = glm::min(box.lo, other.lo);
  box.hi = glm::max(box.hi, other.hi);
}

Aabb surrounding(const Aabb& a, const Aabb& b) {
  Aabb box = a;
  grow(box, b);
  return box;
}

vec3 centroid(const Aabb& box) { return 0.5 * (box.lo + box.hi); }

double surface_area(const Aabb& box) {
  if (is_empty(box)) return 0.0;
  const vec3 e = box.hi - box.lo;
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Aabb bounds(const Sphere& sphere) { return {sphere.center - sphere.radius, sphere.center + sphere.radius}; }

Aabb bounds(const Triangle& triangle) {
  Aabb box;
  grow(box, triangle.a);
  grow(box, triangle.b);
  grow(box, triangle.c);
  return box;
}

Aabb bounds(const Quad& quad) {
  Aabb box;
  for (const vec3& p : {quad.corner, quad.corner + quad.edge_u, quad.corner + quad.edge_v,
                        quad.corner + quad.edge_u + quad.edge_v})
    grow(box, p);
  return box;
}

// Per axis the ray crosses the slab's two planes at t = (lo - o) / d and (hi - o) / d;
// it is in the box from the largest entry to the smallest exit.
//
// A ray parallel to a slab (d = 0 in that axis) has inv_dir = +inf or -inf, so both
// crossings are infinite: -inf and +inf when the origin is inside the slab (no limit),
// both +inf or both -inf when outside (an empty interval: a miss). Only an origin
// exactly on one of the slab's planes gives 0 * inf = NaN. Every comparison with NaN
// is false, so with the updates written as `if (t_near > t_enter) t_enter = t_near`
// a NaN crossing is never taken: the ray counts as inside that slab, as it should
// for a closed box along whose face it runs.
std::optional<double> slab_test(const Ray& ray, const vec3& inv_dir, const Aabb& box) {
  // BEGIN EXERCISE 5.1 ray-box slab test
  double t_enter = ray.t_min;
  double t_exit = ray.t_max * box_reach;  // a hair past t_max: rounding must not cut off a hit at t_max
  for (int axis = 0; axis < 3; ++axis) {
    double t_near = (box.lo[axis] - ray.origin[axis]) * inv_dir[axis];
    double t_far = (box.hi[axis] - ray.origin[axis]) * inv_dir[axis];
    if (inv_dir[axis] < 0) std::swap(t_near, t_far);  // going towards -axis, the ray meets hi first
    if (t_near > t_enter) t_enter = t_near;
    if (t_far < t_exit) t_exit = t_far;
  }
  if (t_enter > t_exit) return std::nullopt;  // equal is a hit: a flat box, or a grazing ray
  return t_enter;
  // END EXERCISE 5.1
}

}  // namespace gi
