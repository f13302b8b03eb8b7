#include "gi/image/metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gi {

namespace {

void check_sizes(const Image& a, const Image& b) {
  if (!a.same_size(b) || a.pixels.empty())
    throw std::invalid_argument("image metrics: the images must have the same, non-zero size");
}

// Mean over pixels and channels of term(a, b), summed in double in pixel order so
// the result is the same whatever produced the images.
template <class Term>
double channel_mean(const Image& a, const Image& b, Term term) {
  check_sizes(a, b);
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) sum += term(double(a.pixels[i][c]), double(b.pixels[i][c]));
  return sum / (3.0 * a.pixels.size());
}

}  // namespace

double mse(const Image& a, const Image& b) {
  return channel_mean(a, b, [](double x, double y) { return (x - y) * (x - y); });
}

double rmse(const Image& a, const Image& b) { return std::sqrt(mse(a, b)); }

double relative_mse(const Image& test, const Image& reference, double epsilon) {
  return channel_mean(test, reference, [epsilon](double t, double r) { return (t - r) * (t - r) / (r * r + epsilon); });
}

double psnr(const Image& a, const Image& b, double peak) {
  const double e = mse(a, b);
  if (e == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / e);
}

}  // namespace gi
