#pragma once
// The (0,m,2)-net property, checked exactly (the unit tests of the samplers and the
// graded lab alike): 2^m points of the unit square, each coordinate a 32-bit binary
// fraction (the value times 2^-32), put exactly one point in every elementary interval
// of area 2^-m,
//   [a 2^-p, (a + 1) 2^-p) x [b 2^-q, (b + 1) 2^-q),   p + q = m.
// That is m + 1 grids at once, from 1 x 2^m through 2^p x 2^q to 2^m x 1.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gi::testing {

using Point32 = std::array<std::uint32_t, 2>;

// "" when the points are a (0,m,2)-net, else a line naming the first interval that holds
// another count than one.
inline std::string net_defect(const std::vector<Point32>& points, int m) {
  if (points.size() != (std::size_t{1} << m))
    return "expected 2^" + std::to_string(m) + " points, got " + std::to_string(points.size());
  for (int p = 0; p <= m; ++p) {
    const int q = m - p;
    std::vector<int> count(std::size_t{1} << m, 0);
    for (const Point32& x : points) {
      const std::uint64_t a = std::uint64_t{x[0]} >> (32 - p), b = std::uint64_t{x[1]} >> (32 - q);
      ++count[(a << q) | b];
    }
    for (std::size_t cell = 0; cell < count.size(); ++cell)
      if (count[cell] != 1)
        return "the interval [" + std::to_string(cell >> q) + "/2^" + std::to_string(p) + ", +1/2^" +
               std::to_string(p) + ") x [" + std::to_string(cell & ((std::size_t{1} << q) - 1)) + "/2^" +
               std::to_string(q) + ", +1/2^" + std::to_string(q) + ") holds " + std::to_string(count[cell]) +
               " of the 2^" + std::to_string(m) + " points, not 1";
  }
  return "";
}

// A coordinate in [0, 1) that is a multiple of 2^-32 (as the samplers make them) as its
// 32 binary digits, exactly.
inline std::uint32_t digits_of(double x) { return static_cast<std::uint32_t>(x * 0x1p32); }

}  // namespace gi::testing
