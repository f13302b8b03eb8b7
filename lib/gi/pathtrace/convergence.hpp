#pragma once
#include <optional>
#include <vector>

namespace gi {

// How fast a Monte Carlo picture's error falls, and so what an error costs it. Scored
// against a reference that is itself noisy -- its own error r by the same measure
// (reference_noise in picture_error.hpp) -- the error e of a picture of N samples per
// pixel obeys, in expectation,
//   e^2 = v / N + r^2
// The picture's deviation from the truth and the reference's are independent, so their
// squares add; v is what one sample per pixel would score against the exact truth
// (squared). The law holds for any error measure that is a sum of squares over the
// picture divided by a fixed number, such as relative RMS over blocks.
struct ErrorAtSamples {
  double spp;    // N, samples per pixel
  double error;  // e, measured against the reference
};

// v from measured errors. Each point alone is an unbiased estimate,
//   v_k = N_k (e_k^2 - r^2),
// negative when its picture happened to land closer than the reference's own noise;
// v is their mean (a point is not dropped for being negative: that would bias v up).
// Throws std::invalid_argument for no points, or an spp below 1, an error or an r that
// is negative or not finite.
double monte_carlo_variance(const std::vector<ErrorAtSamples>& measured, double reference_error);

// The samples per pixel at which the expected error falls to `target`:
//   N = v / (target^2 - r^2)
// Nothing when target <= r: no picture can be shown closer to the truth than the
// reference it is measured against, however long it renders. Throws
// std::invalid_argument for a v, target or r that is negative or not finite.
std::optional<double> samples_for_error(double v, double target, double reference_error);

}  // namespace gi
