#pragma once
#include <array>

#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

// A convex polygon of up to 8 corners, counter-clockwise about its normal: a
// Polygon's outline, or what is left of it after cutting by planes (a convex
// polygon loses a corner or gains one per cut). The analytic form factors and the
// overlap test work on these.
struct ConvexPolygon {
  std::array<vec3, 8> corners{};
  int count = 0;
  vec3 normal{0.0};
};

ConvexPolygon outline(const Polygon& polygon);

// Flat: every corner within 1e-9 of the polygon's size from the plane through its
// centre (round-off); otherwise twisted.
bool is_flat(const Polygon& polygon);

// A polygon as the rays of FormFactorScene meet it: flat, its outline; twisted, its two
// triangles (c0 c1 c2) and (c0 c2 c3), each flat, with its own normal. Methods that
// need a plane -- a depth, a clip, a side -- use these pieces, so that a twisted
// receiver is the same surface for the hemicube, the analytic method and the rays.
struct FlatPieces {
  std::array<ConvexPolygon, 2> pieces;
  int count = 0;
};
FlatPieces flat_pieces(const Polygon& polygon);

// The part of p on the side n . x >= offset of a plane (n unit). A corner within
// `tolerance` of the plane counts as on it: kept, and never the start of a cut, so
// that round-off cannot add slivers along an edge that lies in the plane. Empty
// (count 0) unless some corner lies beyond the tolerance on the kept side: a polygon
// that only touches the plane has no part in front of it.
ConvexPolygon clip(const ConvexPolygon& p, const vec3& n, double offset, double tolerance);

// The area of p projected onto the plane with unit normal n.
double area(const ConvexPolygon& p, const vec3& n);

// The largest distance between two corners of p.
double diameter(const ConvexPolygon& p);

// The shortest distance between two convex polygons that do not pass through each
// other (each on one side of the other's plane): the least of the edge-to-edge and
// corner-to-face distances.
double distance(const ConvexPolygon& a, const ConvexPolygon& b);

// The area two polygons share, measured in a's plane: b projected onto that plane
// and cut by the planes through a's edges at right angles to it.
double overlap_area(const ConvexPolygon& a, const ConvexPolygon& b);

}  // namespace gi
