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

}  // namespace gi
