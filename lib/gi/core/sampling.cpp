#include "gi/core/sampling.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gi {

DiscreteDistribution make_discrete_distribution(const std::vector<double>& weights) {
  if (weights.empty()) throw std::invalid_argument("discrete distribution: no weights");
  DiscreteDistribution d;
  d.cdf.reserve(weights.size());
  double total = 0;
  for (double w : weights) {
    if (!(w >= 0) || !std::isfinite(w))
      throw std::invalid_argument("discrete distribution: weights must be finite and >= 0, got " + std::to_string(w));
    total += w;
    d.cdf.push_back(total);
  }
  if (!(total > 0)) throw std::invalid_argument("discrete distribution: every weight is zero");
  for (double& c : d.cdf) c /= total;
  d.cdf.back() = 1.0;  // exactly, whatever the rounding of the sums
  return d;
}

int sample_discrete(const DiscreteDistribution& d, double u) {
  // The first i with u < cdf[i]: things of weight 0 (cdf[i] = cdf[i - 1]) are never chosen.
  const auto it = std::upper_bound(d.cdf.begin(), d.cdf.end(), u);
  return static_cast<int>(std::min<std::ptrdiff_t>(it - d.cdf.begin(), static_cast<std::ptrdiff_t>(d.cdf.size()) - 1));
}

double discrete_pdf(const DiscreteDistribution& d, int i) {
  if (i < 0 || i >= static_cast<int>(d.cdf.size())) return 0.0;
  return d.cdf[i] - (i > 0 ? d.cdf[i - 1] : 0.0);
}

}  // namespace gi
