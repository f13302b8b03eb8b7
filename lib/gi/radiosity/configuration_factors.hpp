#pragma once
// Exact form factors ("configuration factors") of the heat-transfer literature, for
// the simple shapes every form-factor method is checked against: as catalogued in
// J. R. Howell's "A Catalog of Radiation Heat Transfer Configuration Factors" and in
// Siegel and Howell, "Thermal Radiation Heat Transfer". The tests check each against
// numerical integration as well.

namespace gi {

// Two directly opposed, parallel a x b rectangles a distance c apart: F from one to
// the other (the same both ways, the areas being equal). 0.1998 for a = b = c.
double ff_parallel_rectangles(double a, double b, double c);

// Two rectangles at right angles sharing an edge of length l: from the one of width
// w (away from the edge) to the one of height h. 0.2000 for w = h = l.
double ff_perpendicular_rectangles(double l, double w, double h);

// From a differential area to a parallel a x b rectangle a distance c away, the
// rectangle's corner on the area's normal. 1/4 as a, b grow without bound.
double ff_point_to_parallel_rectangle_corner(double a, double b, double c);

}  // namespace gi
