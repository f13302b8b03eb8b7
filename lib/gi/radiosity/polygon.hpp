#pragma once
#include <array>

#include "gi/core/math.hpp"

namespace gi {

// A flat convex quadrilateral: the shape of a surface, a patch and an element. The
// corners go counter-clockwise seen from the front, the side the normal points to.
// Radiosity surfaces shine and receive on their front only.
struct Polygon {
  std::array<vec3, 4> corners;
  vec3 normal;  // unit
  vec3 centre;  // the centroid of the area
  double area;
};

// Computes the normal, centroid and area from the corners, using the diagonals:
// n = (c2 - c0) x (c3 - c1) / |...|, area = |(c2 - c0) x (c3 - c1)| / 2, exact for a
// planar quadrilateral and the mean plane's for a slightly twisted one (the Cornell
// box's walls are off by up to 3 mm in 550). Throws std::invalid_argument for
// non-finite corners, no area, a twist over 1% of the size or a non-convex shape.
Polygon make_polygon(const std::array<vec3, 4>& corners);

// The bilinear map of the unit square onto the quadrilateral: (0,0) -> c0,
// (1,0) -> c1, (1,1) -> c2, (0,1) -> c3. Splits surfaces into patches and elements
// that share their corners.
vec3 bilinear(const std::array<vec3, 4>& corners, double s, double t);

}  // namespace gi
