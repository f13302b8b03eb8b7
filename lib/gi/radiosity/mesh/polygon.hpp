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

// How far a corner may lie from the polygon's mean plane, as a fraction of its size
// (the longer diagonal). Measured data are rarely exactly flat: the Cornell box's red
// wall is off by 3 mm in 550 (0.6%). Every form-factor method treats a polygon as
// its outline projected onto that plane (see lifted_centre).
inline constexpr double planarity_tolerance = 0.01;

// Throws std::invalid_argument, with one line saying what is wrong, unless:
//  - the corners, normal, centre and area are finite;
//  - the corners span an area, lie within planarity_tolerance of one plane and make
//    a convex quadrilateral, counter-clockwise seen from the normal's side;
//  - the normal is unit length and within 0.5 degrees of the corners' (the diagonals'
//    cross product), the area within 1e-6 of theirs, and the centre inside the
//    outline and on its plane (within the planarity tolerance).
// Every library function that takes a Polygon it did not make checks it this way,
// so a hand-built Polygon{corners, normal, centre, area} is as safe as make_polygon's.
void check(const Polygon& polygon);

// Computes the normal, centroid and area from the corners, using the diagonals:
// n = (c2 - c0) x (c3 - c1) / |...|, area = |(c2 - c0) x (c3 - c1)| / 2, exact for a
// planar quadrilateral and the mean plane's (the outline projected onto it) for a
// slightly twisted one. Throws std::invalid_argument as check() does.
Polygon make_polygon(const std::array<vec3, 4>& corners);

// The highest a corner rises above the plane through the centre, along the normal:
// 0 for a flat polygon, half the twist for a twisted one.
double lift(const Polygon& polygon);

// The centre lifted along the normal to the highest corner: where the hemicube of a
// polygon stands and its rays start. No part of the polygon -- nor of the elements a
// patch is cut into, which lie on the same bilinear surface -- rises above the plane
// through this point, so a twisted patch never blocks its own view.
vec3 lifted_centre(const Polygon& polygon);

// The bilinear map of the unit square onto the quadrilateral: (0,0) -> c0,
// (1,0) -> c1, (1,1) -> c2, (0,1) -> c3. Splits surfaces into patches and elements
// that share their corners.
vec3 bilinear(const std::array<vec3, 4>& corners, double s, double t);

// Its inverse: the (s, t) in [0, 1]^2 of a point p of a flat convex quadrilateral with
// unit normal n, by Newton's method from the middle (the map is nearly affine: three
// steps suffice). The display reads B there; the two-pass renderer and the hierarchy's
// leaf display too.
vec2 unbilinear(const std::array<vec3, 4>& corners, const vec3& n, const vec3& p);

}  // namespace gi
