#include "gi/radiosity/mesh/polygon.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace gi {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("polygon: " + what); }

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string text(const vec3& v) { return '(' + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ')'; }

// What the corners alone say: the diagonals' cross product (twice the area along the
// normal) and the longer diagonal (the size). Throws for corners that span nothing.
struct FromCorners {
  vec3 normal;
  double area;
  double size;
};
FromCorners from_corners(const std::array<vec3, 4>& c) {
  for (int k = 0; k < 4; ++k)
    if (!is_finite(c[k])) fail("corner " + std::to_string(k) + " is not finite " + text(c[k]));
  const vec3 n = cross(c[2] - c[0], c[3] - c[1]);
  const double size = std::max(length(c[2] - c[0]), length(c[3] - c[1]));
  if (!(length(n) > 1e-12 * size * size) || !std::isfinite(length(n)))
    fail("the corners span no area " + text(c[0]) + " " + text(c[1]) + " " + text(c[2]) + " " + text(c[3]));
  const vec3 normal = normalize(n);
  const vec3 mean = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  for (int k = 0; k < 4; ++k) {
    // Every corner near the mean plane, and every turn to the left (convex, CCW).
    const double off = std::abs(dot(c[k] - mean, normal));
    if (off > planarity_tolerance * size)
      fail("the corners are not in one plane: corner " + std::to_string(k) + " is " + number(off / size * 100) +
           "% of the size off it (at most " + number(planarity_tolerance * 100) + "%)");
    if (dot(cross(c[(k + 1) % 4] - c[k], c[(k + 2) % 4] - c[(k + 1) % 4]), normal) <= 0)
      fail("the corners do not make a convex, counter-clockwise quadrilateral (turn at corner " +
           std::to_string((k + 1) % 4) + ")");
  }
  return {normal, 0.5 * length(n), size};
}

}  // namespace

void check(const Polygon& p) {
  const FromCorners c = from_corners(p.corners);
  if (!is_finite(p.normal) || std::abs(length(p.normal) - 1) > 1e-6)
    fail("the normal must be a unit vector, got " + text(p.normal));
  // The corners' normal can differ from the given one by the twist a planar fit allows.
  if (dot(p.normal, c.normal) < std::cos(2 * planarity_tolerance))
    fail("the normal " + text(p.normal) + " is not the corners' " + text(c.normal) +
         " (are the corners clockwise seen from the front?)");
  if (!(std::abs(p.area - c.area) <= 1e-6 * c.area))
    fail("the area " + number(p.area) + " is not the corners' " + number(c.area));
  if (!is_finite(p.centre)) fail("the centre is not finite " + text(p.centre));
  const vec3 mean = 0.25 * (p.corners[0] + p.corners[1] + p.corners[2] + p.corners[3]);
  bool inside = std::abs(dot(p.centre - mean, c.normal)) <= planarity_tolerance * c.size;
  for (int k = 0; k < 4 && inside; ++k) {
    const vec3 edge = p.corners[(k + 1) % 4] - p.corners[k];
    inside = dot(cross(edge, p.centre - p.corners[k]), c.normal) >= -1e-9 * c.size * c.size;
  }
  if (!inside) fail("the centre " + text(p.centre) + " is not inside the outline");
}

Polygon make_polygon(const std::array<vec3, 4>& c) {
  const FromCorners f = from_corners(c);
  // Centroid: of the two triangles (c0 c1 c2) and (c0 c2 c3), weighted by their areas.
  const double a1 = 0.5 * dot(cross(c[1] - c[0], c[2] - c[0]), f.normal);
  const double a2 = 0.5 * dot(cross(c[2] - c[0], c[3] - c[0]), f.normal);
  const vec3 centre = (a1 * (c[0] + c[1] + c[2]) + a2 * (c[0] + c[2] + c[3])) / (3 * (a1 + a2));
  return {c, f.normal, centre, f.area};
}

double lift(const Polygon& p) {
  double highest = 0;
  for (const vec3& corner : p.corners) highest = std::max(highest, dot(corner - p.centre, p.normal));
  return highest;
}

vec3 lifted_centre(const Polygon& p) { return p.centre + lift(p) * p.normal; }

vec3 bilinear(const std::array<vec3, 4>& c, double s, double t) {
  return (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] + (1 - s) * t * c[3];
}

// (s, t) with bilinear(c, s, t) = p for a point p of a flat convex quadrilateral, by
// Newton's method from the middle: the map is nearly affine, three steps suffice, and
// the loop stops once a step moves (s, t) by less than 1e-12 (a parallelogram's map is
// affine: its first step lands, its second only confirms).
vec2 unbilinear(const std::array<vec3, 4>& c, const vec3& n, const vec3& p) {
  vec2 st(0.5, 0.5);
  for (int step = 0; step < 4; ++step) {
    const vec3 r = bilinear(c, st.x, st.y) - p;
    const vec3 ds = (1 - st.y) * (c[1] - c[0]) + st.y * (c[2] - c[3]);
    const vec3 dt = (1 - st.x) * (c[3] - c[0]) + st.x * (c[2] - c[1]);
    // Solve [ds dt] (delta) = r in the plane: Cramer with the normal.
    const double det = dot(cross(ds, dt), n);
    if (std::abs(det) < 1e-300) break;
    const vec2 step_st = vec2(dot(cross(r, dt), n), dot(cross(ds, r), n)) / det;
    st -= step_st;
    if (std::abs(step_st.x) + std::abs(step_st.y) < 1e-12) break;  // converged: the next step moves round-off
  }
  return glm::clamp(st, 0.0, 1.0);
}

}  // namespace gi
