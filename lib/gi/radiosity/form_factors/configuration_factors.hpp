#pragma once
// Exact form factors ("configuration factors") of the heat-transfer literature, for
// the simple shapes every form-factor method is checked against: as catalogued in
// J. R. Howell's "A Catalog of Radiation Heat Transfer Configuration Factors" and in
// Siegel and Howell, "Thermal Radiation Heat Transfer". The tests check each against
// numerical integration as well.
//
// Written to keep their precision at every size and separation, to about 1e-14
// relative in double (none needs long double's extra digits; thin offset rectangles
// nearer than 2 sizes, 2e-13): the textbook forms subtract nearly equal logarithms and
// arctangents, and far apart lose every digit (the parallel-rectangle formula gives
// exactly 0 at 10^6 sizes). Where that happens these use log1p, differences of
// arctangents, a series, or, for the general offset rectangles from 2 sizes apart, the
// smooth integral itself.
// Every function throws std::invalid_argument for lengths that are not positive and
// finite, or a configuration outside its description.

namespace gi {

// Two directly opposed, parallel a x b rectangles a distance c apart: F from one to
// the other (the same both ways, the areas being equal). 0.1998 for a = b = c.
// Beyond c^2 = 4 (a^2 + b^2) the series
//   F = xy/pi sum_k (k+1) (-1)^k sum_m C(k,m) mu_m(x) mu_(k-m)(y),  mu_m(z) = 2 z^2m / ((2m+1)(2m+2))
// with x = a/c, y = b/c: the kernel c^2 / (pi (c^2 + rho^2)^2) expanded in rho^2/c^2
// and averaged over the two rectangles (mu_m is the mean of (dx/c)^2m for two
// uniform points of a side).
double ff_parallel_rectangles(double a, double b, double c);

// Two rectangles at right angles sharing an edge of length l: from the one of width
// w (away from the edge) to the one of height h. 0.2000 for w = h = l.
double ff_perpendicular_rectangles(double l, double w, double h);

// From a differential area to a parallel a x b rectangle a distance c away, the
// rectangle's corner on the area's normal. 1/4 as a, b grow without bound.
double ff_point_to_parallel_rectangle_corner(double a, double b, double c);

// From a differential area to an a x b rectangle in a plane at right angles to the
// area's, at distance c from it: the side of length a lies in the area's plane, one
// end at the foot of the perpendicular from the area; the side b rises from the
// area's plane. 1/4 as a, b grow and c shrinks.
//   F = (atan(a/c) - c/sqrt(b^2 + c^2) atan(a/sqrt(b^2 + c^2))) / (2 pi)
double ff_point_to_perpendicular_rectangle_corner(double a, double b, double c);

// Two parallel rectangles with sides along x and y, facing each other across a gap
// z: [x1, x2] x [y1, y2] in one plane and [xi1, xi2] x [eta1, eta2] in the other. F
// from the first to the second, the sum of 16 corner terms
//   A_1 F_12 = sum (-1)^(i+j+k+l) G(x_i - xi_k, y_j - eta_l),
//   G(x, y) = 1/(2 pi) [x sqrt(y^2 + z^2) atan(x / sqrt(y^2 + z^2))
//                       + y sqrt(x^2 + z^2) atan(y / sqrt(x^2 + z^2)) - z^2/2 ln(x^2 + y^2 + z^2)]
// summed in gi::wide (gi/core/wide_float.hpp). Far apart those terms cancel (they grow
// like distance^2, their sum shrinks like 1 / distance^2): where the round-off left
// would pass 1e-14 of F, and the centres are 2 sizes apart or more, the integral
// itself by Gauss-Legendre over both rectangles (positive and smooth there); nearer,
// for thin rectangles, the sum over halves of them.
double ff_parallel_rectangles_offset(double x1, double x2, double y1, double y2, double xi1, double xi2, double eta1,
                                     double eta2, double z);

// Two rectangles in perpendicular planes meeting along the y axis: the first in the
// plane z = 0 over x in [x1, x2] (0 <= x1), y in [y1, y2], facing +z; the second in
// the plane x = 0 over y in [eta1, eta2], z in [z1, z2] (0 <= z1), facing +x. F from
// the first to the second:
//   A_1 F_12 = sum (-1)^(i+j+k+l) G(x_i, y_j, eta_k, z_l),
//   G = 1/(2 pi) [(y - eta) s atan((y - eta) / s) - (s^2 - (y - eta)^2)/4 ln(s^2 + (y - eta)^2)],
//   s^2 = x^2 + z^2,
// as the offset parallel case is computed, near and far. With x1 = z1 = 0 and equal
// y ranges it is ff_perpendicular_rectangles.
double ff_perpendicular_rectangles_offset(double x1, double x2, double y1, double y2, double eta1, double eta2,
                                          double z1, double z2);

}  // namespace gi
