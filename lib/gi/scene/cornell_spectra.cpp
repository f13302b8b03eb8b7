#include "gi/scene/cornell_spectra.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gi {

double band_mean(const Spectrum& s, double lo, double hi) {
  const std::size_t n = s.wavelength_nm.size();
  if (n < 2 || s.value.size() != n || !(lo < hi) || lo < s.wavelength_nm.front() || hi > s.wavelength_nm.back())
    throw std::invalid_argument("band_mean: band [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                "] nm must lie inside the spectrum's samples (at least two)");
  // s(lambda) between samples i and i+1, linearly interpolated.
  auto at = [&](std::size_t i, double lambda) {
    const double t = (lambda - s.wavelength_nm[i]) / (s.wavelength_nm[i + 1] - s.wavelength_nm[i]);
    return s.value[i] + t * (s.value[i + 1] - s.value[i]);
  };
  // Each interval's overlap with [lo, hi] is a trapezoid: (b - a) (s(a) + s(b)) / 2.
  double integral = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double a = std::max(lo, s.wavelength_nm[i]), b = std::min(hi, s.wavelength_nm[i + 1]);
    if (a < b) integral += (b - a) * (at(i, a) + at(i, b)) / 2;
  }
  return integral / (hi - lo);
}

Color rgb_band_means(const Spectrum& s) {
  return Color(band_mean(s, 600, 700), band_mean(s, 500, 600), band_mean(s, 400, 500));
}

namespace {

// The data page's reflectances are sampled at 400, 404, ..., 700 nm (76 values).
Spectrum every_4nm_from_400(std::vector<double> value) {
  Spectrum s;
  for (std::size_t i = 0; i < value.size(); ++i) s.wavelength_nm.push_back(400.0 + 4.0 * double(i));
  s.value = std::move(value);
  return s;
}

}  // namespace

// The three reflectance spectra, copied from the Cornell box data page.
Spectrum cornell_white_spectrum() {
  return every_4nm_from_400({
    0.343, 0.445, 0.551, 0.624, 0.665, 0.687, 0.708, 0.723, 0.715, 0.71, 0.745, 0.758,
    0.739, 0.767, 0.777, 0.765, 0.751, 0.745, 0.748, 0.729, 0.745, 0.757, 0.753, 0.75,
    0.746, 0.747, 0.735, 0.732, 0.739, 0.734, 0.725, 0.721, 0.733, 0.725, 0.732, 0.743,
    0.744, 0.748, 0.728, 0.716, 0.733, 0.726, 0.713, 0.74, 0.754, 0.764, 0.752, 0.736,
    0.734, 0.741, 0.74, 0.732, 0.745, 0.755, 0.751, 0.744, 0.731, 0.733, 0.744, 0.731,
    0.712, 0.708, 0.729, 0.73, 0.727, 0.707, 0.703, 0.729, 0.75, 0.76, 0.751, 0.739,
    0.724, 0.73, 0.74, 0.737,
  });
}

Spectrum cornell_red_spectrum() {
  return every_4nm_from_400({
    0.04, 0.046, 0.048, 0.053, 0.049, 0.05, 0.053, 0.055, 0.057, 0.056, 0.059, 0.057,
    0.061, 0.061, 0.06, 0.062, 0.062, 0.062, 0.061, 0.062, 0.06, 0.059, 0.057, 0.058,
    0.058, 0.058, 0.056, 0.055, 0.056, 0.059, 0.057, 0.055, 0.059, 0.059, 0.058, 0.059,
    0.061, 0.061, 0.063, 0.063, 0.067, 0.068, 0.072, 0.08, 0.09, 0.099, 0.124, 0.154,
    0.192, 0.255, 0.287, 0.349, 0.402, 0.443, 0.487, 0.513, 0.558, 0.584, 0.62, 0.606,
    0.609, 0.651, 0.612, 0.61, 0.65, 0.638, 0.627, 0.62, 0.63, 0.628, 0.642, 0.639,
    0.657, 0.639, 0.635, 0.642,
  });
}

Spectrum cornell_green_spectrum() {
  return every_4nm_from_400({
    0.092, 0.096, 0.098, 0.097, 0.098, 0.095, 0.095, 0.097, 0.095, 0.094, 0.097, 0.098,
    0.096, 0.101, 0.103, 0.104, 0.107, 0.109, 0.112, 0.115, 0.125, 0.14, 0.16, 0.187,
    0.229, 0.285, 0.343, 0.39, 0.435, 0.464, 0.472, 0.476, 0.481, 0.462, 0.447, 0.441,
    0.426, 0.406, 0.373, 0.347, 0.337, 0.314, 0.285, 0.277, 0.266, 0.25, 0.23, 0.207,
    0.186, 0.171, 0.16, 0.148, 0.141, 0.136, 0.13, 0.126, 0.123, 0.121, 0.122, 0.119,
    0.114, 0.115, 0.117, 0.117, 0.118, 0.12, 0.122, 0.128, 0.132, 0.139, 0.144, 0.146,
    0.15, 0.152, 0.157, 0.159,
  });
}

// The light's emission as published: 0 at 400 nm, 8 at 500, 15.6 at 600, 18.4 at 700.
Spectrum cornell_light_spectrum() { return {{400, 500, 600, 700}, {0.0, 8.0, 15.6, 18.4}}; }

}  // namespace gi
