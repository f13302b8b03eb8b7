#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/report/table.hpp"

namespace gi {

// Shooting in a furnace: where progressive refinement needs reciprocity.
//
// Gathering uses each element's own row: B_i = E_i + rho_i sum_j F_ij B_j. In a closed
// room every row of F sums to 1 (every direction from i meets a surface), so a white
// furnace (E = 1 and rho everywhere) comes out B = E / (1 - rho) exactly, whatever the
// method's error in the single F_ij.
//
// Shooting uses the shooter's row for the receivers: j receives rho_j dB_p F_pj A_p / A_j
// (progressive.hpp), F_jp by reciprocity. Element j then gathers, in effect, over the
// column of F: sum_p F_pj A_p / A_j, which is 1 only if the method's F is reciprocal,
// A_p F_pj = A_j F_jp. The analytic factors are (to their 1e-10); a hemicube's and Monte
// Carlo's are not: each is one element's view, measured from that element (its centre,
// or its rays), and two elements see their pair differently. So the furnace misses by
// what the columns miss by.
//
// Shooting with the receivers' own rows instead, j receiving rho_j F_jp dB_p with F_jp
// from j's row, keeps the furnace: it is the gathering system solved by shooting (as
// lesson 12's showdown does), and needs every row -- the matrix shooting was meant to
// do without.

// One row of the study: a form-factor method, how far its matrix is from a closed room's
// sums and from reciprocity, and a solver's furnace.
struct ShootingFurnaceRow {
  std::string form_factors, solver;
  double row_sums = 0;      // max_i |sum_j F_ij - 1|
  double column_sums = 0;   // max_j |sum_i A_i F_ij / A_j - 1|: what shooting hands j per unit B
  double nonreciprocal = 0; // sum_ij |A_i F_ij - A_j F_ji| / sum_ij (A_i F_ij + A_j F_ji)
  double furnace = 0;       // max over elements and channels of |B / (E / (1 - rho)) - 1|
  int steps = 0;
};

// The empty closed box (closed_box(1)) meshed into about `elements` elements as a white
// furnace (E = 1, rho = 0.5): for the hemicube (resolution 100), Monte Carlo (256 rays
// per row) and the analytic factors, Gauss-Seidel on the rows, shooting with the
// shooter's row and shooting with the receivers' rows, each to 1e-9 (residual, or
// unshot energy). Same rows for any thread count.
std::vector<ShootingFurnaceRow> shooting_furnace(int elements, int threads);

// The study as the lesson prints it.
Table shooting_furnace_table(const std::vector<ShootingFurnaceRow>& rows);

}  // namespace gi
