#pragma once
#include "gi/radiosity/mesh/convex_polygon.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"

namespace gi {

// The form factor from one polygon to another by Sparrow's double contour integral
// (Stokes' theorem applied to both areas of the form-factor integral):
//   A_i F_ij = 1/(2 pi) sum over edges a of i, b of j of (e_a . e_b) int_a int_b ln r ds dt
// with e_a, e_b the edges' unit directions, each polygon counter-clockwise about its
// normal. Exact when each polygon lies wholly in front of the other: clip them first.
//
// For each pair of edges the inner integral, along b, is a closed form: with d the
// distance from the point of a to b's line and u measured along that line,
//   int ln sqrt(u^2 + d^2) du = u ln sqrt(u^2 + d^2) - u + d atan(u / d).
// The outer one, along a, is adaptive (integrate_adaptive): the integrand is smooth
// except where the edges meet -- a shared edge, a shared corner -- where it has a
// logarithmic singularity that the intervals close in on. This is what makes the
// method exact in the near field and at shared edges, where a fixed rule over the
// area is not. The sum is symmetric in the two polygons: the thinner one's edges are
// the inner ones, and a thin rectangle's two long sides are one difference there, so a
// strip 1e-6 wide keeps its digits in double. `area_from` is A_i, the sender's whole
// area.
Estimate form_factor_double_contour(const ConvexPolygon& from, const ConvexPolygon& to, double area_from,
                                    double relative_tolerance, int max_evaluations = 400000);

}  // namespace gi
