#include "gi/geometry/sphere.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "gi/core/not_implemented.hpp"

namespace gi {

void check(const Sphere& sphere) {
  if (!is_finite(sphere.center) || !std::isfinite(sphere.radius) || sphere.radius <= 0)
    throw std::invalid_argument("sphere: the radius must be positive and finite and the centre finite, got radius " +
                                std::to_string(sphere.radius));
}

std::optional<Hit> intersect(const Ray& ray, const Sphere& sphere) {
  // |o + t d - c|^2 = r^2  is  a t^2 + 2 h t + c0 = 0  with  a = d.d, h = d.(o - c),
  // c0 = |o - c|^2 - r^2. Return the nearest root in [t_min, t_max].
  // BEGIN EXERCISE 1.1 ray-sphere intersection
  const vec3 oc = ray.origin - sphere.center;
  const double a = dot(ray.direction, ray.direction);
  const double h = dot(ray.direction, oc);
  const double c0 = dot(oc, oc) - sphere.radius * sphere.radius;
  if (c0 > 0 && h > 0) return std::nullopt;  // outside and heading away: both roots are negative
  // The textbook discriminant h^2 - a c0 is cheap but carries a rounding error of
  // about eps * h^2, which for a small sphere far away is larger than the answer.
  // So it only rejects clear misses; what is left is decided by the same quantity
  // in a form without the cancellation: (a^2 r^2 - |a oc - h d|^2) / a.
  if (h * h - a * c0 < -4 * std::numeric_limits<double>::epsilon() * h * h) return std::nullopt;
  const vec3 offset = a * oc - h * ray.direction;  // a times the line's offset from the centre
  const double discriminant = (a * a * sphere.radius * sphere.radius - dot(offset, offset)) / a;
  if (discriminant < 0) return std::nullopt;

  // Try the nearer root first; if it lies behind t_min (the ray starts inside the
  // sphere, or the sphere is behind it) the farther root may still be in range.
  const double root = std::sqrt(discriminant);
  double t = (-h - root) / a;
  if (t < ray.t_min || t > ray.t_max) {
    t = (-h + root) / a;
    if (t < ray.t_min || t > ray.t_max) return std::nullopt;
  }
  const vec3 point = ray.at(t);
  return Hit{t, point, (point - sphere.center) / sphere.radius, sphere.material};
  // END EXERCISE 1.1
}

}  // namespace gi
