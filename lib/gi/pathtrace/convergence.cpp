#include "gi/pathtrace/convergence.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gi/core/not_implemented.hpp"

namespace gi {

namespace {

void check_non_negative(double value, const char* what) {
  if (!(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("Monte Carlo error law: ") + what + " must be a finite number >= 0, got " +
                                std::to_string(value));
}

}  // namespace

double monte_carlo_variance(const std::vector<ErrorAtSamples>& measured, double reference_error) {
  if (measured.empty()) throw std::invalid_argument("Monte Carlo error law: no measured errors to fit");
  check_non_negative(reference_error, "the reference's error");
  for (const ErrorAtSamples& point : measured) {
    if (!(point.spp >= 1) || !std::isfinite(point.spp))
      throw std::invalid_argument("Monte Carlo error law: samples per pixel must be >= 1, got " +
                                  std::to_string(point.spp));
    check_non_negative(point.error, "an error");
  }
  // BEGIN EXERCISE 15.1 the Monte Carlo variance from measured errors
  // v_k = N_k (e_k^2 - r^2): the picture's own share of its squared error, times N
  double sum = 0;
  for (const ErrorAtSamples& point : measured)
    sum += point.spp * (point.error * point.error - reference_error * reference_error);
  return sum / static_cast<double>(measured.size());
  // END EXERCISE 15.1
}

std::optional<double> samples_for_error(double v, double target, double reference_error) {
  check_non_negative(v, "v");
  check_non_negative(target, "the target error");
  check_non_negative(reference_error, "the reference's error");
  // BEGIN EXERCISE 15.2 the samples per pixel an error costs
  // e^2 = v / N + r^2  =>  N = v / (e^2 - r^2), only while e > r
  if (!(target > reference_error)) return std::nullopt;
  return v / (target * target - reference_error * reference_error);
  // END EXERCISE 15.2
}

}  // namespace gi
