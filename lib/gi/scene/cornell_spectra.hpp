#pragma once
#include <vector>

#include "gi/core/math.hpp"

namespace gi {

// A spectrum as the Cornell box data page lists it: values at increasing wavelengths
// (nm), linear in between.
struct Spectrum {
  std::vector<double> wavelength_nm;
  std::vector<double> value;
};

// The mean of a piecewise-linear spectrum over [lo, hi] nm (the trapezoid rule is exact
// for it): (1 / (hi - lo)) * integral_lo^hi s(lambda) d lambda. Throws
// std::invalid_argument unless lo < hi lies inside the spectrum's range.
double band_mean(const Spectrum& spectrum, double lo_nm, double hi_nm);

// The bands an RGB renderer stands for: B = [400, 500], G = [500, 600], R = [600, 700] nm.
// Returns (R, G, B) band means. McGuire's widely used light (17, 12, 4) is exactly the
// published light's band means (17.0, 11.8, 4.0) rounded, which is why these bands.
Color rgb_band_means(const Spectrum& spectrum);

// The published data (www.graphics.cornell.edu/online/box/data.html): the measured
// reflectance of the box's white, red and green paint, 400..700 nm every 4 nm, and the
// light's emission spectrum (taken here as radiance L).
Spectrum cornell_white_spectrum();
Spectrum cornell_red_spectrum();
Spectrum cornell_green_spectrum();
Spectrum cornell_light_spectrum();

}  // namespace gi
