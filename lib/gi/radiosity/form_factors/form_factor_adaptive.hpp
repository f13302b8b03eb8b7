#pragma once
#include "gi/radiosity/mesh/polygon.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"

namespace gi {

// The analytic method's form factor from one polygon to another, nothing in
// between, to a relative `tolerance`, with the estimate of its error beside it:
//   F_ij = 1/A_i int over A_i of F(dA_i -> A_j) dA_i
// where F(dA_i -> A_j), from a point, is Lambert's contour integral (exact).
//
// First each polygon is cut to the part in front of the other (the integrand is 0
// elsewhere, and its kinks there would spoil any quadrature). Then:
//  - far apart (the gap at least a quarter of the sender's width), the integrand is
//    smooth over the sender, and Gauss-Legendre rules over it converge fast: orders
//    n, 2n, 4n ... from `first_order` until two agree to the tolerance; the last
//    difference is the error estimate (it bounds the lower order's error, so it is
//    generous for the higher one);
//  - close (near field, shared edges and corners, thin strips on wide patches), it is
//    not: the double contour integral (double_contour.hpp) is used, whose adaptive
//    quadrature closes in on the singular corners and edges.
// The sender is its outline projected onto the plane through lifted_centre, so a
// twisted patch never gets light from its own elements (as with every method).
// Throws std::invalid_argument for an invalid polygon (check) or tolerance outside
// [1e-14, 0.1]; otherwise always finite, and 0 exactly for a polygon to itself.
Estimate form_factor_analytic_adaptive(const Polygon& from, const Polygon& to, double tolerance = 1e-10,
                                       int first_order = 4);

}  // namespace gi
