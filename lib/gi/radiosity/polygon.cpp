#include "gi/radiosity/polygon.hpp"

#include <stdexcept>

namespace gi {

Polygon make_polygon(const std::array<vec3, 4>& c) {
  for (const vec3& p : c)
    if (!is_finite(p)) throw std::invalid_argument("polygon: corners must be finite");
  const vec3 n = cross(c[2] - c[0], c[3] - c[1]);
  const double size = std::max(length(c[2] - c[0]), length(c[3] - c[1]));
  if (!(length(n) > 1e-12 * size * size)) throw std::invalid_argument("polygon: the corners span no area");
  const vec3 normal = normalize(n);
  for (int i = 0; i < 4; ++i) {
    // Every corner near the mean plane, and every turn to the left (convex, CCW).
    if (std::abs(dot(c[i] - 0.25 * (c[0] + c[1] + c[2] + c[3]), normal)) > 0.01 * size)
      throw std::invalid_argument("polygon: the corners are not in one plane");
    if (dot(cross(c[(i + 1) % 4] - c[i], c[(i + 2) % 4] - c[(i + 1) % 4]), normal) <= 0)
      throw std::invalid_argument("polygon: the corners do not make a convex, counter-clockwise quadrilateral");
  }
  // Centroid: of the two triangles (c0 c1 c2) and (c0 c2 c3), weighted by their areas.
  const double a1 = 0.5 * dot(cross(c[1] - c[0], c[2] - c[0]), normal);
  const double a2 = 0.5 * dot(cross(c[2] - c[0], c[3] - c[0]), normal);
  const vec3 centre = (a1 * (c[0] + c[1] + c[2]) + a2 * (c[0] + c[2] + c[3])) / (3 * (a1 + a2));
  return {c, normal, centre, 0.5 * length(n)};
}

vec3 bilinear(const std::array<vec3, 4>& c, double s, double t) {
  return (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] + (1 - s) * t * c[3];
}

}  // namespace gi
