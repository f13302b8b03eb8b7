// Sobol's first two dimensions: their first points by hand, and the (0,2)-sequence
// property, exactly: every block of 2^m consecutive points is a (0,m,2)-net.
#include "gi/core/samplers/sobol.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "support/nets.hpp"

namespace t = gi::testing;

namespace {

std::vector<t::Point32> sobol_block(std::uint32_t first, int m) {
  std::vector<t::Point32> points;
  for (std::uint32_t i = first; i < first + (1u << m); ++i) points.push_back({gi::sobol(i, 0), gi::sobol(i, 1)});
  return points;
}

}  // namespace

TEST(Sobol, FirstPointsByHand) {
  // Dimension 0: the bits of i mirrored, 0, 1/2, 1/4, 3/4, 1/8, ... Dimension 1, from
  // x + 1 and m_1 = 1: m_k = 2 m_(k-1) xor m_(k-1) gives m = 1, 3, 5, 15, so
  // v = 1/2, 3/4, 5/8, 15/16, and x(3) = v_1 xor v_2 = 0.10 xor 0.11 = 0.01 = 1/4.
  const double dim0[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double dim1[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(gi::sobol(i, 0) * 0x1p-32, dim0[i]) << "point " << i << " of dimension 0";
    EXPECT_EQ(gi::sobol(i, 1) * 0x1p-32, dim1[i]) << "point " << i << " of dimension 1";
  }
  EXPECT_EQ(gi::sobol(8, 1) * 0x1p-32, 15.0 / 16) << "v_4 = m_4 / 2^4 = 15/16";
  EXPECT_EQ(gi::sobol(0xffffffffu, 0), 0xffffffffu) << "every bit of i set: every digit set";
}

TEST(Sobol, FirstPointsAreANetForEveryPowerOfTwo) {
  for (int m = 0; m <= 16; ++m) EXPECT_EQ(t::net_defect(sobol_block(0, m), m), "") << "the first 2^" << m << " points";
}

TEST(Sobol, EveryLaterBlockIsANetToo) {
  // A (0,2)-sequence: the points k 2^m ... (k + 1) 2^m - 1 are a net for every k, so a
  // renderer that goes on past 2^m samples starts a new net where the last one ended.
  for (int m : {1, 4, 7, 10})
    for (std::uint32_t k : {1u, 2u, 3u, 77u, 1000u, (1u << (31 - m)) - 1})
      EXPECT_EQ(t::net_defect(sobol_block(k << m, m), m), "") << "block " << k << " of 2^" << m;
}

TEST(Sobol, OnlyTwoDimensionsAreKept) {
  EXPECT_THROW(gi::sobol(1, 2), std::invalid_argument);
  EXPECT_THROW(gi::sobol(1, -1), std::invalid_argument);
}
