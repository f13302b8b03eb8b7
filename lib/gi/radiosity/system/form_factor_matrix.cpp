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

FormFactorMatrix between_groups(const FormFactorMatrix& F, const std::vector<double>& areas,
                                const std::vector<int>& group, int groups) {
  if (static_cast<int>(areas.size()) != F.n || static_cast<int>(group.size()) != F.n)
    throw std::invalid_argument("between_groups: one area and one group per element");
  FormFactorMatrix grouped{groups, std::vector<double>(static_cast<std::size_t>(groups) * groups, 0.0)};
  std::vector<double> area(groups, 0.0);
  for (int i = 0; i < F.n; ++i) {
    if (group[i] < 0 || group[i] >= groups) throw std::invalid_argument("between_groups: a group out of range");
    area[group[i]] += areas[i];
    for (int j = 0; j < F.n; ++j) grouped(group[i], group[j]) += areas[i] * F(i, j);
  }
  for (int g = 0; g < groups; ++g) {
    if (!(area[g] > 0)) throw std::invalid_argument("between_groups: a group with no area");
    for (int h = 0; h < groups; ++h) grouped(g, h) /= area[g];
  }
  return grouped;
}

}  // namespace gi
