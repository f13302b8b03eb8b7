// Stratified sampling: the grid of strata, the random permutations that give each
// decision its own order of strata, and the points: one in every stratum, exactly.
//
// Statistical tests: 2 chi-square tests here, each passing at p > 1e-6.
#include "gi/core/samplers/stratified.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "gi/core/samplers/sample_stream.hpp"
#include "gi/core/samplers/seeds.hpp"
#include "support/statistics.hpp"

namespace t = gi::testing;

TEST(StrataGrid, AsSquareAsTheNumberAllows) {
  const std::uint32_t cases[][3] = {{1, 1, 1},   {2, 1, 2},   {4, 2, 2},   {7, 1, 7},      {8, 2, 4},
                                    {12, 3, 4},  {16, 4, 4},  {18, 3, 6},  {4096, 64, 64}, {4095, 63, 65},
                                    {65537, 1, 65537}, {0xffffffffu, 65535, 65537}};
  for (const auto& c : cases) {
    const gi::StrataGrid g = gi::strata_grid(c[0]);
    EXPECT_EQ(g.nx, c[1]) << "N = " << c[0];
    EXPECT_EQ(g.ny, c[2]) << "N = " << c[0];
  }
  EXPECT_THROW(gi::strata_grid(0), std::invalid_argument);
}

TEST(PermutationElement, IsAPermutation) {
  for (std::uint32_t n = 1; n <= 300; ++n)
    for (std::uint64_t seed : {0ull, 1ull, 0x9e3779b97f4a7c15ull}) {
      std::vector<int> hits(n, 0);
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t p = gi::permutation_element(i, n, seed);
        ASSERT_LT(p, n) << "n = " << n;
        ++hits[p];
      }
      for (std::uint32_t p = 0; p < n; ++p) ASSERT_EQ(hits[p], 1) << "element " << p << " of [0, " << n << ")";
    }
  std::vector<char> hit(100003, 0);
  for (std::uint32_t i = 0; i < 100003; ++i) hit[gi::permutation_element(i, 100003, 42)] = 1;
  EXPECT_EQ(std::count(hit.begin(), hit.end(), 1), 100003);
}

TEST(PermutationElement, EveryOrderedPairIsEquallyLikely) {
  // Over seeds, where elements 0 and 1 of a permutation of [0, 10) go: each of the 90
  // ordered pairs equally often (chi-square), as for a uniformly random permutation. A
  // family of permutations that were only shifts would reach 10 pairs of the 90.
  const int seeds = 90000;
  for (std::uint32_t n : {3u, 10u, 16u, 64u}) {
    std::vector<double> observed(n * n, 0), expected(n * n, 0);
    for (int s = 0; s < seeds; ++s) {
      const std::uint64_t seed = gi::child_seed(2024, s);
      observed[gi::permutation_element(0, n, seed) * n + gi::permutation_element(1, n, seed)] += 1;
    }
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = 0; b < n; ++b)
        if (a != b) expected[a * n + b] = double(seeds) / (n * (n - 1));
    const t::ChiSquare c = t::chi_square_test(observed, expected);
    EXPECT_GT(c.p_value, 1e-6) << "n = " << n << ": chi-square " << c.statistic << " on " << c.degrees_of_freedom
                               << " degrees of freedom";
  }
}

TEST(Jittered, PointsStayInsideTheirStratum) {
  EXPECT_EQ(gi::jittered_1d(0, 4, 0), 0.0);
  EXPECT_EQ(gi::jittered_1d(3, 4, 0x80000000u), 0.875);
  EXPECT_LT(gi::jittered_1d(2, 3, 0xffffffffu), 1.0);
  EXPECT_GE(gi::jittered_1d(2, 3, 0xffffffffu), 2.0 / 3);
  const gi::vec2 u = gi::jittered_2d(5, {2, 4}, 0, 0x80000000u);  // column 1, row 2 of 2 x 4
  EXPECT_EQ(u.x, 0.5);
  EXPECT_EQ(u.y, 0.625);
}

TEST(Jittered, EveryStratumHoldsOneSampleOfEveryDecision) {
  // Samples 0 ... N - 1 of a pixel (and N ... 2N - 1, the next stratified set) put one
  // point in each of the N strata of every 1D decision and each of the nx x ny cells
  // of every 2D one.
  for (std::uint32_t n : {1u, 2u, 7u, 16u, 18u, 64u, 1024u}) {
    const gi::SampleSequence sampler = gi::make_sample_sequence(gi::SamplerKind::Stratified, 99, n);
    for (std::uint64_t pixel : {0ull, 1ull, 123456789ull})
      for (std::uint32_t set : {0u, 1u})
        for (std::uint32_t d = 0; d < 12; ++d) {
          std::vector<int> strata(n, 0), cells(n, 0);
          for (std::uint32_t i = set * n; i < (set + 1) * n; ++i) {
            const gi::SampleStream stream(sampler, pixel, i);
            const double x = stream.get_1d(d);
            const gi::vec2 u = stream.get_2d(d);
            ASSERT_GE(x, 0.0);
            ASSERT_LT(x, 1.0);
            ++strata[std::size_t(x * n)];
            ++cells[std::size_t(u.y * sampler.strata.ny) * sampler.strata.nx + std::size_t(u.x * sampler.strata.nx)];
          }
          for (std::uint32_t s = 0; s < n; ++s) {
            ASSERT_EQ(strata[s], 1) << "N = " << n << ", pixel " << pixel << ", dimension " << d << ": 1D stratum " << s;
            ASSERT_EQ(cells[s], 1) << "N = " << n << ", pixel " << pixel << ", dimension " << d << ": 2D cell " << s;
          }
        }
  }
}
