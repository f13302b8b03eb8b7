#include "gi/radiosity/system/form_factor_matrix.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

double reciprocity_error(const FormFactorMatrix& F, const std::vector<double>& areas, double floor) {
  if (static_cast<int>(areas.size()) != F.n) throw std::invalid_argument("reciprocity: one area per element");
  // BEGIN EXERCISE 6.3 the reciprocity check
  double worst = 0;
  for (int i = 0; i < F.n; ++i)
    for (int j = i + 1; j < F.n; ++j) {
      const double ij = areas[i] * F(i, j), ji = areas[j] * F(j, i);
      const double larger = std::max(ij, ji);
      if (larger > floor) worst = std::max(worst, std::abs(ij - ji) / larger);
    }
  return worst;
  // END EXERCISE 6.3
}

std::vector<double> row_sums(const FormFactorMatrix& F) {
  std::vector<double> sums(F.n, 0.0);
  for (int i = 0; i < F.n; ++i)
    for (int j = 0; j < F.n; ++j) sums[i] += F(i, j);
  return sums;
}

}  // namespace gi
