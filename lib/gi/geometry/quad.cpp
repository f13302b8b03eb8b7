#include "gi/geometry/quad.hpp"

#include <stdexcept>

namespace gi {

vec3 normal(const Quad& quad) { return normalize(cross(quad.edge_u, quad.edge_v)); }
double area(const Quad& quad) { return length(cross(quad.edge_u, quad.edge_v)); }
vec3 centre(const Quad& quad) { return quad.corner + 0.5 * (quad.edge_u + quad.edge_v); }

std::array<Quad, 6> box_quads(const vec3& lo, const vec3& hi, int material) {
  const vec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
  return {Quad{lo, dz, dy, material},      Quad{lo + dx, dy, dz, material},  // -x, +x
          Quad{lo, dx, dz, material},      Quad{lo + dy, dz, dx, material},  // -y, +y
          Quad{lo, dy, dx, material},      Quad{lo + dz, dx, dy, material}}; // -z, +z
}

void check(const Quad& quad) {
  if (!is_finite(quad.corner) || !is_finite(quad.edge_u) || !is_finite(quad.edge_v))
    throw std::invalid_argument("quad: corner and edges must be finite");
  const double scale = length(quad.edge_u) * length(quad.edge_v);
  if (!(scale > 0) || area(quad) <= 1e-12 * scale)
    throw std::invalid_argument("quad: the edges are zero or parallel, so the quad has no area");
}

std::optional<Hit> intersect(const Ray& ray, const Quad& quad) {
  const vec3 n = cross(quad.edge_u, quad.edge_v);  // not normalised: |n| = area
  const double denominator = dot(ray.direction, n);
  const double t = dot(quad.corner - ray.origin, n) / denominator;
  if (t < ray.t_min || t > ray.t_max) return std::nullopt;  // (a NaN t, of a ray in the plane, goes on)

  // Coordinates (s, t) of the hit in the edge basis: with w = n / |n|^2,
  // s = w.((p - corner) x edge_v) and t = w.(edge_u x (p - corner)).
  const vec3 point = ray.at(t);
  const vec3 p = point - quad.corner;
  const vec3 w = n / dot(n, n);
  const double s = dot(w, cross(p, quad.edge_v));
  const double u = dot(w, cross(quad.edge_u, p));
  if (s < 0 || s > 1 || u < 0 || u > 1) return std::nullopt;
  // A ray (nearly) parallel to the plane has no single hit. Tested last, as its two
  // square roots are needed only by a ray that passed the rest: the order of the
  // rejections changes no value and no answer, only how soon a miss is known.
  if (std::abs(denominator) < 1e-12 * length(ray.direction) * length(n)) return std::nullopt;
  return Hit{t, point, normalize(n), quad.material};
}

}  // namespace gi
