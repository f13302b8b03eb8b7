// Graded tests of exercise 14.7: Owen's scramble, the random bit of each digit. One
// point per test.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/core/samplers/owen_scramble.hpp"
#include "gi/core/samplers/sobol.hpp"
#include "support/nets.hpp"
#include "support/print.hpp"
#include "support/statistics.hpp"

namespace t = gi::testing;

namespace {

// Digit k (1 = the highest) of a 32-bit fraction.
int digit(std::uint32_t v, int k) { return (v >> (32 - k)) & 1u; }

}  // namespace

TEST(Ex14_7_OwenScramble, TheFirstDigitsFlipByTheBitsOfTheirNodes) {
  // Digit 1 is flipped by the bit of node 1 (the whole of [0, 1)); digit 2 by node
  // 2 + d_1 (the half it lies in); digit 3 by node 4 + 2 d_1 + d_2 (its quarter).
  gi::Rng rng(71);
  for (int trial = 0; trial < 200; ++trial) {
    const std::uint32_t v = rng.next_u32(), seed = rng.next_u32(), s = gi::owen_scramble(v, seed);
    const int d1 = digit(v, 1), d2 = digit(v, 2), d3 = digit(v, 3);
    ASSERT_EQ(digit(s, 1), d1 ^ gi::scramble_bit(seed, 1))
        << "digit 1 has no digits above it: flip it by scramble_bit(seed, 1), the node of [0, 1)";
    ASSERT_EQ(digit(s, 2), d2 ^ gi::scramble_bit(seed, 2 + d1))
        << "digit 2 lies in the half d_1: flip it by the bit of node 2 + d_1 (node = 2^(k-1) + the k-1 digits above)";
    ASSERT_EQ(digit(s, 3), d3 ^ gi::scramble_bit(seed, 4 + 2 * d1 + d2))
        << "digit 3 lies in the quarter d_1 d_2: flip it by the bit of node 4 + 2 d_1 + d_2";
  }
}

TEST(Ex14_7_OwenScramble, KeepsEveryDyadicInterval) {
  // Two values in one interval of length 2^-k (the same first k digits) must land in
  // one interval of length 2^-k, and in different halves of it if they were: sharing
  // exactly k first digits afterwards too.
  gi::Rng rng(72);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::uint32_t seed = rng.next_u32(), a = rng.next_u32();
    const int k = trial % 32;
    const std::uint32_t b = a ^ (0x80000000u >> k) ^ (rng.next_u32() & (0x7fffffffu >> k));
    ASSERT_EQ(std::countl_zero(gi::owen_scramble(a, seed) ^ gi::owen_scramble(b, seed)), k)
        << "two values sharing their first " << k << " digits must share exactly " << k
        << " after the scramble: the flip of a digit may depend on the digits above it only, never on itself or "
           "those below, and must land at that digit (bit 31 - k for digit k + 1)";
  }
}

TEST(Ex14_7_OwenScramble, SobolsPointsStayANet) {
  for (int m = 1; m <= 10; ++m) {
    std::vector<t::Point32> points;
    for (std::uint32_t i = 0; i < (1u << m); ++i)
      points.push_back({gi::owen_scramble(gi::sobol(i, 0), 7 * m), gi::owen_scramble(gi::sobol(i, 1), 11 * m)});
    const std::string defect = t::net_defect(points, m);
    ASSERT_EQ(defect, "") << "the scrambled first 2^" << m << " Sobol' points are no longer a (0," << m
                          << ",2)-net: a scramble must map each dyadic interval onto one of the same size";
  }
}

TEST(Ex14_7_OwenScramble, ScramblesAllThirtyTwoDigits) {
  // The point 0 over 4000 seeds: every digit comes out 1 in about half of them
  // (Binomial(4000, 1/2): 2000 +- 31.6; 5 standard deviations allowed).
  std::vector<int> ones(33, 0);
  for (std::uint32_t s = 0; s < 4000; ++s) {
    const std::uint32_t x = gi::owen_scramble(0, s * 2654435761u);
    for (int k = 1; k <= 32; ++k) ones[k] += digit(x, k);
  }
  for (int k = 1; k <= 32; ++k)
    EXPECT_NEAR(ones[k], 2000, 5 * 31.6) << "digit " << k << " of the scrambled point 0 is 1 in " << ones[k]
                                          << " of 4000 seeds, not about half: scramble all 32 digits, each by the "
                                             "bit of its own node";
}

TEST(Ex14_7_OwenScramble, EachIntervalFlipsItsDigitsOnItsOwn) {
  // Values that differ first at digit j lie in different intervals below it, so their
  // digits k > j are flipped by the bits of different nodes: over many seeds the two
  // flips agree about half the time (2000 +- 31.6 of 4000). Flipping digit k alike
  // everywhere (a random digital shift) makes them always agree.
  gi::Rng rng(74);
  for (int j : {1, 2, 9, 24}) {
    const std::uint32_t a = rng.next_u32() & ~(0x80000000u >> (j - 1)), b = a | (0x80000000u >> (j - 1));
    for (int k : {j + 1, j + 2, j + 7}) {
      if (k > 32) continue;
      int agree = 0;
      for (int s = 0; s < 4000; ++s) {
        const std::uint32_t seed = rng.next_u32();
        agree += (digit(gi::owen_scramble(a, seed), k) ^ digit(a, k)) == (digit(gi::owen_scramble(b, seed), k) ^ digit(b, k));
      }
      EXPECT_NEAR(agree, 2000, 5 * 31.6)
          << "values that differ first at digit " << j << " had digit " << k << " flipped alike in " << agree
          << " of 4000 seeds: the node of digit " << k << " must hold all " << k - 1
          << " digits above it, so that each interval gets its own random bit";
    }
  }
}

TEST(Ex14_7_OwenScramble, EachPointAloneIsUniform) {
  // One point over 40000 seeds falls uniformly in [0, 1): chi-square on 64 cells
  // (p > 1e-6). Nodes of different depths that share a number (the digits above
  // without the depth's leading 1) would tie the digits of the point 0 together.
  for (std::uint32_t v : {0u, 0xffffffffu, 0x2b7e1516u}) {
    std::vector<double> observed(64, 0);
    for (std::uint32_t s = 0; s < 40000; ++s) observed[gi::owen_scramble(v, s * 2654435761u) >> 26] += 1;
    const t::ChiSquare c = t::chi_square_test(observed, std::vector<double>(64, 40000 / 64.0));
    EXPECT_GT(c.p_value, 1e-6) << "the scrambled point " << v << " is not uniform over seeds (chi-square "
                               << c.statistic << " on 63 degrees of freedom): number the node of digit k "
                               << "as 2^(k-1) + the digits above it, so that no two nodes share a bit";
  }
}

TEST(Ex14_7_OwenScramble, ErrorFallsAsNToTheMinusThreeHalves) {
  // The integral of exp(-(x^2 + y^2)) over the unit square by N scrambled Sobol'
  // points, over 64 seeds: the RMS error against the exact ((sqrt(pi) / 2) erf(1))^2
  // falls as about N^-3/2 (Owen 1997; N^-1.40 with the reference solution), where a
  // random digital shift reaches only N^-1, as jittered samples do.
  const double exact = std::pow(std::sqrt(gi::pi) / 2 * std::erf(1.0), 2);
  std::vector<double> log_n, log_rms;
  for (std::uint32_t n = 4; n <= 1024; n *= 4) {
    double squared = 0;
    for (std::uint32_t s = 0; s < 64; ++s) {
      double sum = 0;
      for (std::uint32_t i = 0; i < n; ++i) {
        const double x = gi::owen_scramble(gi::sobol(i, 0), 2 * s + 1000 * n) * 0x1p-32;
        const double y = gi::owen_scramble(gi::sobol(i, 1), 2 * s + 1 + 1000 * n) * 0x1p-32;
        sum += std::exp(-(x * x + y * y));
      }
      squared += std::pow(sum / n - exact, 2) / 64;
    }
    log_n.push_back(std::log(double(n)));
    log_rms.push_back(0.5 * std::log(squared));
  }
  const double slope = (log_rms.back() - log_rms.front()) / (log_n.back() - log_n.front());
  EXPECT_LT(slope, -1.3) << "the error falls as N^" << slope << ", not about N^-1.5: each interval's digits "
                         << "must be flipped by a bit of their own (a flip shared by all intervals is a digital "
                            "shift, N^-1)";
  EXPECT_GT(slope, -1.7) << "the error falls as N^" << slope << ", faster than an unbiased scramble can";
}
