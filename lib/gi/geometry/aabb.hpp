#pragma once
#include <limits>
#include <optional>

#include "gi/core/ray.hpp"
#include "gi/geometry/quad.hpp"
#include "gi/geometry/sphere.hpp"
#include "gi/geometry/triangle.hpp"

namespace gi {

// An axis-aligned bounding box: the points x with lo <= x <= hi in every axis.
// The default box is empty (lo = +inf, hi = -inf), so growing it by a first point
// or box gives exactly that point or box.
struct Aabb {
  vec3 lo{std::numeric_limits<double>::infinity()};
  vec3 hi{-std::numeric_limits<double>::infinity()};
};

bool is_empty(const Aabb& box);
void grow(Aabb& box, const vec3& point);
void grow(Aabb& box, const Aabb& other);
Aabb surrounding(const Aabb& a, const Aabb& b);  // the smallest box holding both
vec3 centroid(const Aabb& box);
double surface_area(const Aabb& box);  // 0 for an empty box

// The tightest boxes around the shapes. A quad's box is flat (zero thickness) when
// the quad lies in an axis-aligned plane, as walls and floors do.
Aabb bounds(const Sphere& sphere);
Aabb bounds(const Quad& quad);
Aabb bounds(const Triangle& triangle);

// The slab test (Kay and Kajiya 1986): the box is the intersection of three slabs,
// lo.x <= x <= hi.x and so on; the ray is inside each slab for an interval of t, and
// inside the box where all three intervals and [ray.t_min, ray.t_max] overlap.
// `inv_dir` is 1 / ray.direction per component, computed once per ray: a box test
// then multiplies instead of divides. Returns the distance at which the ray enters
// the box, clipped to ray.t_min (so a ray starting inside gets t_min), or nothing
// when the overlap is empty. The box is closed: a ray grazing a face or an edge, or
// running inside a face's plane, hits it.
//
// The ray's end counts as ray.t_max * box_reach, a billionth further. A box is only a
// filter, and its crossings come from other arithmetic than a primitive's t: a ray
// cut exactly at a hit (t_max = the hit's t, as a shadow ray to a point on a surface)
// entered the flat box of that hit's wall a rounding past t_max (one such ray in six in
// quad_room) and lost the hit. Letting in a box a hair too far costs a visit now and
// then, never a wrong hit: the primitives still test [t_min, t_max] exactly.
inline constexpr double box_reach = 1 + 1e-9;
std::optional<double> slab_test(const Ray& ray, const vec3& inv_dir, const Aabb& box);

}  // namespace gi
