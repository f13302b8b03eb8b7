#include "gi/geometry/plane.hpp"

#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

void check(const Plane& plane) {
  if (!is_finite(plane.point) || !is_finite(plane.normal) || std::abs(length(plane.normal) - 1.0) > 1e-9)
    throw std::invalid_argument("plane: the normal must be a finite unit vector and the point finite");
}

std::optional<Hit> intersect(const Ray& ray, const Plane& plane) {
  // (o + t d - p).n = 0  gives  t = (p - o).n / (d.n).
  // BEGIN EXERCISE 1.2 ray-plane intersection
  const double denominator = dot(ray.direction, plane.normal);
  // A ray (nearly) parallel to the plane never meets it; dividing would give inf or
  // a wildly large t that round-off alone decided.
  if (std::abs(denominator) < 1e-12 * length(ray.direction)) return std::nullopt;
  const double t = dot(plane.point - ray.origin, plane.normal) / denominator;
  if (t < ray.t_min || t > ray.t_max) return std::nullopt;
  return Hit{t, ray.at(t), plane.normal, plane.material};
  // END EXERCISE 1.2
}

}  // namespace gi
