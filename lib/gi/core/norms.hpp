#pragma once
// Sums of squares that neither underflow nor overflow. A light 1e-300 times dimmer
// gives radiosities near 1e-300, whose squares are 0 in double: a relative RMS
// sqrt(sum d^2 / sum B^2) becomes 0/0. Dividing every value by one number near the
// largest first keeps the squares near 1 (LAPACK's dnrm2 scales the same way), and
// when that number is a power of two the division is exact: where nothing underflowed
// the result has the very bytes of the plain sum.
#include <cmath>
#include <vector>

#include "gi/core/math.hpp"

namespace gi {

// 2^-e with largest * 2^-e in [0.5, 1): multiplying by it is exact. 1 for 0, and for
// a largest that is not finite (the sums then say so themselves).
inline double power_of_two_scale(double largest) {
  if (!(largest > 0) || !std::isfinite(largest)) return 1;
  int e = 0;
  (void)std::frexp(largest, &e);
  return std::ldexp(1.0, -e);
}

// The largest |channel| over a list of colours.
inline double largest_channel(const std::vector<Color>& v) {
  double m = 0;
  for (const Color& c : v) m = std::max(m, max_component(glm::abs(c)));
  return m;
}

}  // namespace gi
