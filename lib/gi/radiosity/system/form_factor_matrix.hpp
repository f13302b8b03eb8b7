#pragma once
#include <vector>

namespace gi {

// The n x n form-factor matrix between elements, F_ij = the fraction of the energy
// leaving element i that arrives at element j, stored row by row.
struct FormFactorMatrix {
  int n = 0;
  std::vector<double> values;  // F_ij at i * n + j

  double operator()(int i, int j) const { return values[static_cast<std::size_t>(i) * n + j]; }
  double& operator()(int i, int j) { return values[static_cast<std::size_t>(i) * n + j]; }
};

// Reciprocity says A_i F_ij = A_j F_ji: the energy exchanged either way is the same
// fraction of the same product. The worst relative violation over all pairs,
//   max |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji),
// over the pairs where either side exceeds `floor`; 0 for a perfect matrix.
double reciprocity_error(const FormFactorMatrix& F, const std::vector<double>& areas, double floor = 1e-12);

// sum_j F_ij for each i: 1 in a closed room, less where some of the view escapes.
std::vector<double> row_sums(const FormFactorMatrix& F);

// The form factors between groups of elements (a wall, a block, the light), each
// element i in group[i] of 0 .. groups - 1: the area-weighted mean of the rows,
//   F_GH = sum_{i in G} A_i sum_{j in H} F_ij / sum_{i in G} A_i,
// which is what the area-to-area definition gives for the union of the elements. Rows
// keep their sums (1 in a closed room), and a reciprocal F gives a reciprocal answer,
// A_G F_GH = A_H F_HG. Throws std::invalid_argument for a group out of range or one
// with no area.
FormFactorMatrix between_groups(const FormFactorMatrix& F, const std::vector<double>& areas,
                                const std::vector<int>& group, int groups);

}  // namespace gi
