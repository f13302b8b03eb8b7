#include "gi/core/samplers/sobol.hpp"

#include <array>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace gi {

namespace {

using DirectionNumbers = std::array<std::uint32_t, 32>;  // v_1 ... v_32, as 32-bit fractions

// The direction numbers of the primitive polynomial of degree s whose middle
// coefficients a_1 ... a_(s-1) are the bits of `a` (a_1 the highest), from m_1 ... m_s.
constexpr DirectionNumbers direction_numbers(int s, std::uint32_t a, std::initializer_list<std::uint64_t> initial) {
  std::array<std::uint64_t, 33> m{};  // m[k] for k = 1 ... 32
  int k = 1;
  for (const std::uint64_t value : initial) m[k++] = value;
  for (; k <= 32; ++k) {
    m[k] = m[k - s] ^ (m[k - s] << s);
    for (int j = 1; j < s; ++j)
      if ((a >> (s - 1 - j)) & 1u) m[k] ^= m[k - j] << j;
  }
  DirectionNumbers v{};
  for (k = 1; k <= 32; ++k) v[k - 1] = static_cast<std::uint32_t>(m[k] << (32 - k));  // v_k = m_k / 2^k
  return v;
}

constexpr DirectionNumbers van_der_corput = [] {
  DirectionNumbers v{};
  for (int k = 1; k <= 32; ++k) v[k - 1] = 1u << (32 - k);
  return v;
}();
constexpr DirectionNumbers x_plus_1 = direction_numbers(1, 0, {1});

}  // namespace

std::uint32_t sobol(std::uint32_t index, int dimension) {
  if (dimension != 0 && dimension != 1)
    throw std::invalid_argument("Sobol' sequence: dimension " + std::to_string(dimension) +
                                " is not kept (0 and 1 are: pad further decisions with scrambled copies)");
  const DirectionNumbers& v = dimension == 0 ? van_der_corput : x_plus_1;
  std::uint32_t x = 0;
  for (int k = 0; index != 0; ++k, index >>= 1)
    if (index & 1u) x ^= v[k];
  return x;
}

}  // namespace gi
