// Owen's scramble by its definition and by the Laine-Karras hash: both must map every
// dyadic interval onto one of the same size (so nets stay nets), make each point alone
// uniform, and flip the digits of different intervals independently.
//
// Statistical tests: 6 here (3 per scramble), each with a false-failure chance of
// about 1e-6 or less (5 standard errors, or a chi-square p below 1e-6); the seeds are
// fixed, so the outcome is too.
#include "gi/core/samplers/owen_scramble.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/core/samplers/sobol.hpp"
#include "support/nets.hpp"
#include "support/statistics.hpp"

namespace t = gi::testing;

namespace {

using Scramble = std::function<std::uint32_t(std::uint32_t, std::uint32_t)>;

struct Named {
  const char* name;
  Scramble scramble;
};

void PrintTo(const Named& scramble, std::ostream* os) { *os << scramble.name; }

class OwenScramble : public ::testing::TestWithParam<Named> {};

INSTANTIATE_TEST_SUITE_P(BothWays, OwenScramble,
                         ::testing::Values(Named{"definition", gi::owen_scramble},
                                           Named{"hashed", gi::owen_scramble_hashed}),
                         [](const auto& info) { return std::string(info.param.name); });

// How many leading digits two words share.
int shared_digits(std::uint32_t a, std::uint32_t b) { return std::countl_zero(a ^ b); }

}  // namespace

TEST(ReverseBits, MirrorsTheWord) {
  EXPECT_EQ(gi::reverse_bits(1u), 0x80000000u);
  EXPECT_EQ(gi::reverse_bits(0x80000000u), 1u);
  EXPECT_EQ(gi::reverse_bits(0x0000000fu), 0xf0000000u);
  EXPECT_EQ(gi::reverse_bits(0x12345678u), 0x1e6a2c48u);
  gi::Rng rng(3);
  for (int k = 0; k < 1000; ++k) {
    const std::uint32_t v = rng.next_u32();
    ASSERT_EQ(gi::reverse_bits(gi::reverse_bits(v)), v);
  }
}

TEST_P(OwenScramble, KeepsEveryDyadicInterval) {
  // Two values that share their first k digits (lie in one interval of length 2^-k)
  // must come out sharing exactly k: the same interval mapped to one interval, and the
  // two halves below it kept apart. Pairs are made to share 0 to 31 digits.
  const Scramble& scramble = GetParam().scramble;
  gi::Rng rng(5);
  for (int trial = 0; trial < 4000; ++trial) {
    const std::uint32_t seed = rng.next_u32(), a = rng.next_u32();
    const int k = trial % 32;
    const std::uint32_t b = a ^ (0x80000000u >> k) ^ (rng.next_u32() & (0x7fffffffu >> k));
    ASSERT_EQ(shared_digits(scramble(a, seed), scramble(b, seed)), k)
        << std::hex << a << " and " << b << " share " << std::dec << k << " digits, seed " << seed;
  }
}

TEST_P(OwenScramble, KeepsSobolsNet) {
  const Scramble& scramble = GetParam().scramble;
  gi::Rng rng(7);
  for (int m = 1; m <= 12; ++m)
    for (int trial = 0; trial < 4; ++trial) {
      const std::uint32_t seed_x = rng.next_u32(), seed_y = rng.next_u32();
      std::vector<t::Point32> points;
      for (std::uint32_t i = 0; i < (1u << m); ++i)
        points.push_back({scramble(gi::sobol(i, 0), seed_x), scramble(gi::sobol(i, 1), seed_y)});
      ASSERT_EQ(t::net_defect(points, m), "") << "2^" << m << " points, seeds " << seed_x << ", " << seed_y;
    }
}

TEST_P(OwenScramble, EachPointAloneIsUniform) {
  // Over many scrambles, one point (0, 1/2 and an arbitrary one) falls uniformly in
  // [0, 1): 64 cells, chi-square; its mean 1/2 and variance 1/12 within 5 standard errors.
  const Scramble& scramble = GetParam().scramble;
  const int seeds = 40000;
  for (std::uint32_t v : {0u, 0x80000000u, 0x5a17c3e9u}) {
    std::vector<double> observed(64, 0), values;
    for (int s = 0; s < seeds; ++s) {
      const double x = scramble(v, std::uint32_t(s) * 2654435761u) * 0x1p-32;
      observed[std::size_t(x * 64)] += 1;
      values.push_back(x);
    }
    const t::ChiSquare c = t::chi_square_test(observed, std::vector<double>(64, seeds / 64.0));
    EXPECT_GT(c.p_value, 1e-6) << "point " << v << ": chi-square " << c.statistic;
    const t::Estimate mean = t::estimate(values);
    EXPECT_NEAR(mean.mean, 0.5, 5 * mean.standard_error) << "point " << v;
    std::vector<double> squares;
    for (double x : values) squares.push_back((x - 0.5) * (x - 0.5));
    const t::Estimate variance = t::estimate(squares);
    EXPECT_NEAR(variance.mean, 1.0 / 12, 5 * variance.standard_error) << "point " << v;
  }
}

TEST_P(OwenScramble, IntervalsFlipTheirDigitsIndependently) {
  // Two values that differ first at digit j: for every digit k below it, whether digit k
  // is flipped must be decided afresh for each of the two intervals, so over many seeds
  // the two flips agree half the time. A scramble that flips digit k alike everywhere
  // (a random digital shift) makes them agree always.
  const Scramble& scramble = GetParam().scramble;
  gi::Rng rng(11);
  const int seeds = 4000;
  for (int j : {0, 1, 5, 20}) {
    const std::uint32_t a = rng.next_u32() & ~(0x80000000u >> j), b = a | (0x80000000u >> j);
    for (int k = j + 1; k < 32; k += 3) {
      const std::uint32_t bit = 0x80000000u >> k;
      int agree = 0;
      for (int s = 0; s < seeds; ++s) {
        const std::uint32_t seed = rng.next_u32();
        agree += (((scramble(a, seed) ^ a) & bit) != 0) == (((scramble(b, seed) ^ b) & bit) != 0);
      }
      // Binomial(4000, 1/2): standard deviation 31.6.
      EXPECT_NEAR(agree, seeds / 2, 5 * 31.6) << "values apart from digit " << j + 1 << ", flips of digit " << k + 1;
    }
  }
}
