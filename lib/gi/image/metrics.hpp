#pragma once
#include "gi/image/image.hpp"

namespace gi {

// Image comparison, over all pixels and the three channels. Every function throws
// std::invalid_argument when the two images differ in size.
double mse(const Image& a, const Image& b);
double rmse(const Image& a, const Image& b);
// Relative MSE, mean of (t - r)^2 / (r^2 + epsilon): errors in dark regions count
// as much as in bright ones; epsilon keeps black pixels from dividing by zero.
double relative_mse(const Image& test, const Image& reference, double epsilon = 1e-2);
// Peak signal-to-noise ratio in dB, 10 log10(peak^2 / MSE); +inf for identical images.
double psnr(const Image& a, const Image& b, double peak = 1.0);

}  // namespace gi
