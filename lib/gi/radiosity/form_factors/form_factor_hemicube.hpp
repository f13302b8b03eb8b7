#pragma once
#include <vector>

#include "gi/radiosity/system/form_factor_matrix.hpp"

#include "gi/radiosity/form_factors/item_buffer.hpp"

namespace gi {

// One row of the form-factor matrix by the hemicube: render every polygon into the
// item buffer of a hemicube on `from`'s lifted centre, then add up the delta form
// factors of the cells each polygon covers: F_from,j = sum over j's cells of dF.
// Beside the row, how far to trust it: the receivers whose image is smaller than one
// cell get a multiple of a cell's dF or nothing -- aliasing, not a form factor.
struct HemicubeRow {
  std::vector<double> F;
  int sub_cell_receivers = 0;  // facing the hemicube, image under one cell (hidden or not)
  int sub_cell_missed = 0;     // of those, how many no cell centre fell in: F = 0
  double sub_cell_share = 0;   // the share of the hemicube's 3 r^2 cells their images would cover
};
// `weights` must be of the resolution wanted; `buffer` is scratch memory kept between
// rows. Throws std::invalid_argument for an invalid `from` (check); the polygons must
// be valid already, as a FormFactorScene's are (form_factor_row_hemicube checks them).
HemicubeRow hemicube_row(const std::vector<Polygon>& polygons, const Polygon& from, const HemicubeWeights& weights,
                         ItemBuffer& buffer);

// The row alone; throws std::invalid_argument, naming it, for an invalid polygon.
std::vector<double> form_factor_row_hemicube(const std::vector<Polygon>& polygons, const Polygon& from,
                                             const HemicubeWeights& weights, ItemBuffer& buffer);

// Totals of the rows' sub-cell receivers, for lesson 07 and for choosing a resolution.
struct HemicubeMatrixStats {
  long long sub_cell_receivers = 0;
  long long sub_cell_missed = 0;
  int rows_with_sub_cell_receivers = 0;
  double worst_sub_cell_share = 0;  // the largest HemicubeRow::sub_cell_share of any row
  // One more row's counts into the totals (the matrix's rows, or shooting's one by one).
  void add_row(int receivers, int missed, double share) {
    sub_cell_receivers += receivers;
    sub_cell_missed += missed;
    rows_with_sub_cell_receivers += receivers > 0;
    worst_sub_cell_share = share > worst_sub_cell_share ? share : worst_sub_cell_share;
  }
};

// The whole matrix, one hemicube per polygon, rows in parallel on `threads` threads
// (0: all cores). Each row depends only on the geometry: the same matrix for any
// thread count. `stats`, when given, receives the rows' totals.
FormFactorMatrix form_factor_matrix_hemicube(const std::vector<Polygon>& polygons, int resolution, int threads,
                                             HemicubeMatrixStats* stats = nullptr);

}  // namespace gi
