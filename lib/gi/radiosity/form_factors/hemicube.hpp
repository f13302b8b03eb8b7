#pragma once
#include <array>
#include <optional>
#include <vector>

#include "gi/core/math.hpp"

namespace gi {

// The hemicube (Cohen and Greenberg 1985): half a cube of side 2 around a patch's
// centre, its top face at distance 1 along the normal. Everything the patch sees
// projects onto one of the five faces; a face is a grid of cells, and a cell's delta
// form factor is the form factor from the patch to that little square. Summing the
// delta form factors of the cells an element covers gives the element's form factor.
//
// Hemicube coordinates: z along the patch normal, x and y along the tangents. The
// top face is z = 1, -1 <= x, y <= 1, res x res cells. Each side face is half a face:
// res cells across and res/2 up (0 <= z <= 1), since the lower half lies below the
// patch's horizon. res is even.
enum class HemicubeFace { Top, PlusX, MinusX, PlusY, MinusY };
inline constexpr int hemicube_faces = 5;

// Delta form factor of a top-face cell of area dA centred at (x, y, 1):
//   dF = dA / (pi (x^2 + y^2 + 1)^2)
double delta_form_factor_top(double x, double y, double cell_area);

// Delta form factor of a side-face cell of area dA centred at height z on the face
// x = 1 (or any side face, with u the coordinate across the face):
//   dF = z dA / (pi (u^2 + z^2 + 1)^2)
double delta_form_factor_side(double u, double z, double cell_area);

// Where a direction from the hemicube's centre meets the hemicube: the face and the
// cell (column, row) there, or nothing for a direction below the horizon (z <= 0).
// Top: column from x = -1, row from y = -1. Side faces: column along the face's
// tangent coordinate from -1 (PlusX and MinusX use y, PlusY and MinusY use x), row
// from z = 0 upwards.
struct HemicubeCell {
  HemicubeFace face;
  int column;
  int row;
};
std::optional<HemicubeCell> project_to_hemicube(const vec3& direction, int resolution);

// The delta form factors of every cell, computed once per resolution and scaled so
// that they sum to 1: the midpoint values dF above sum to 1 + O(1/res^2), and a room
// whose rows do not sum to 1 gains or loses energy at every bounce.
struct HemicubeWeights {
  int resolution;                 // cells across the top face (even, 2..2000)
  std::vector<double> top;        // res x res, row-major (row = y)
  std::vector<double> side;       // res/2 rows of res, row 0 at the horizon; the same for all four sides
  double unnormalised_sum = 1.0;  // what the midpoint values summed to before the scaling
  double sum() const;             // 1 to round-off (a compensated sum)
};
HemicubeWeights hemicube_weights(int resolution);  // throws std::invalid_argument for odd or bad res

}  // namespace gi
