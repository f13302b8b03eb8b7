#include "gi/geometry/triangle.hpp"

#include <cmath>
#include <stdexcept>

namespace gi {

void check(const Triangle& t) {
  if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c))
    throw std::invalid_argument("triangle: corners must be finite");
  const double scale = length(t.b - t.a) * length(t.c - t.a);
  if (!(scale > 0) || length(cross(t.b - t.a, t.c - t.a)) <= 1e-12 * scale)
    throw std::invalid_argument("triangle: the corners are on one line, so it has no area");
}

std::optional<Hit> intersect(const Ray& ray, const Triangle& triangle) {
  const vec3 e1 = triangle.b - triangle.a, e2 = triangle.c - triangle.a;
  const vec3 p = cross(ray.direction, e2);
  const double determinant = dot(e1, p);
  // Parallel to the triangle's plane (relative to the sizes involved): no hit.
  if (std::abs(determinant) <= 1e-14 * length(e1) * length(p)) return std::nullopt;
  const double inverse = 1.0 / determinant;
  const vec3 s = ray.origin - triangle.a;
  // The edges are widened by a hair (1e-12 of the barycentric range) so that two
  // triangles sharing an edge leave no crack for a ray to slip through by round-off.
  constexpr double hair = 1e-12;
  const double u = dot(s, p) * inverse;
  if (u < -hair || u > 1 + hair) return std::nullopt;
  const vec3 q = cross(s, e1);
  const double v = dot(ray.direction, q) * inverse;
  if (v < -hair || u + v > 1 + hair) return std::nullopt;
  const double t = dot(e2, q) * inverse;
  if (!(t >= ray.t_min && t <= ray.t_max)) return std::nullopt;
  return Hit{t, ray.at(t), normalize(cross(e1, e2)), triangle.material};
}

}  // namespace gi
