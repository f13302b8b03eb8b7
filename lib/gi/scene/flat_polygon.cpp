#include "gi/scene/flat_polygon.hpp"

#include <cstdio>
#include <stdexcept>

#include "gi/geometry/triangle.hpp"

namespace gi {

namespace {

bool has_area(const vec3& a, const vec3& b, const vec3& c) {
  try {
    check(Triangle{a, b, c, 0});
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

// The checks of make_polygon (radiosity/mesh/polygon.cpp), on the same quantities: the
// normal from the diagonals, the size the longer diagonal, the plane through the
// corners' mean.
std::string quadrilateral_problem(const std::array<vec3, 4>& c) {
  const vec3 n = cross(c[2] - c[0], c[3] - c[1]);
  const double size = std::max(length(c[2] - c[0]), length(c[3] - c[1]));
  if (!(length(n) > 1e-12 * size * size)) return "the corners span no area";
  const vec3 normal = normalize(n), mean = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  double off = 0;
  for (const vec3& p : c) off = std::max(off, std::abs(dot(p - mean, normal)) / size);
  if (off > flatness_tolerance) {
    char text[128];
    std::snprintf(text, sizeof text,
                  "the corners are not in one plane (a corner is %.2g%% of its size off it; at most %g%%)", 100 * off,
                  100 * flatness_tolerance);
    return text;
  }
  for (int i = 0; i < 4; ++i)
    if (dot(cross(c[(i + 1) % 4] - c[i], c[(i + 2) % 4] - c[(i + 1) % 4]), normal) <= 0)
      return "the corners do not make a convex quadrilateral (list them in order around it)";
  return "";
}

}  // namespace

int flat_pieces(const FlatPolygon& polygon, std::array<std::array<vec3, 4>, 3>& pieces) {
  const auto& c = polygon.corners;
  if (polygon.count == 4) {
    pieces[0] = c;
    return 1;
  }
  const vec3 g = (c[0] + c[1] + c[2]) / 3.0;
  const vec3 m01 = 0.5 * (c[0] + c[1]), m12 = 0.5 * (c[1] + c[2]), m20 = 0.5 * (c[2] + c[0]);
  pieces[0] = {c[0], m01, g, m20};
  pieces[1] = {c[1], m12, g, m01};
  pieces[2] = {c[2], m20, g, m12};
  return 3;
}

std::string polygon_problem(const FlatPolygon& polygon) {
  if (polygon.count != 3 && polygon.count != 4) return "a polygon has 3 or 4 corners";
  const auto& c = polygon.corners;
  for (int i = 0; i < polygon.count; ++i)
    if (!is_finite(c[i])) return "the corners must be finite";
  if (polygon.count == 4) {
    if (std::string problem = quadrilateral_problem(c); !problem.empty()) return problem;
    if (!has_area(c[0], c[1], c[2]) || !has_area(c[0], c[2], c[3]))
      return "three of the corners are on one line; make it a triangle";
    return "";
  }
  if (!has_area(c[0], c[1], c[2])) return "the corners are on one line, so it has no area";
  std::array<std::array<vec3, 4>, 3> pieces;
  for (int i = 0; i < flat_pieces(polygon, pieces); ++i)
    if (!quadrilateral_problem(pieces[i]).empty()) return "the triangle is too thin to be cut into quadrilaterals";
  return "";
}

}  // namespace gi
