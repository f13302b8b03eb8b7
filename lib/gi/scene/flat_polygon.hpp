#pragma once
#include <array>
#include <string>

#include "gi/core/math.hpp"

namespace gi {

// A polygon of a scene file or an OBJ mesh: a triangle (count 3) or a quadrilateral
// (count 4), flat and convex, corners counter-clockwise seen from its front. The ray
// tracer renders it as triangles, radiosity as flat quadrilaterals (flat_pieces).
struct FlatPolygon {
  std::array<vec3, 4> corners;
  int count = 4;
};

// How far a corner may lie off the mean plane, as a fraction of the polygon's size
// (its longer diagonal): radiosity's planarity_tolerance (radiosity/mesh/polygon.hpp), one
// floor up, with which a test keeps it equal.
inline constexpr double flatness_tolerance = 0.01;

// An empty string if the polygon is fit for both renderers, else what is wrong, in
// a few words ("the corners are not in one plane (3% of its size off it; at most 1%)"):
//  - every corner finite;
//  - a quadrilateral: it spans an area, is flat within flatness_tolerance and convex,
//    as make_polygon requires, and both of its triangles (c0 c1 c2) and (c0 c2 c3)
//    have an area (triangle.hpp), which the ray tracer needs;
//  - a triangle: it has an area, and so do the three quadrilaterals it is cut into.
std::string polygon_problem(const FlatPolygon& polygon);

// Radiosity's surfaces are quadrilaterals. A quadrilateral is its own piece; a
// triangle a b c is cut into three, each joining a corner, the midpoints of its two
// edges and the centroid g:  (a, m_ab, g, m_ca), (b, m_bc, g, m_ab), (c, m_ca, g, m_bc).
// Each is convex (its angle at g is one of the angles b g c, c g a, a g b, all below
// 180 degrees) and counter-clockwise like the triangle, and together they tile it.
// Returns the number of pieces written to `pieces` (1 or 3).
int flat_pieces(const FlatPolygon& polygon, std::array<std::array<vec3, 4>, 3>& pieces);

}  // namespace gi
