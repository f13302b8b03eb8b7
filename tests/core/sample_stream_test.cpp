// The per-pixel, per-sample streams a path tracer draws its decisions from: pure
// functions of (sampler, pixel, sample, dimension); Sobol' nets in every dimension
// after every power of two; each number uniform; dimensions and pixels independent.
//
// Statistical tests: 4 tests of uniformity and independence here, each with a false-
// failure chance of about 1e-6 (chi-square p > 1e-6, or 5 standard errors).
#include "gi/core/samplers/sample_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "support/nets.hpp"
#include "support/statistics.hpp"

namespace t = gi::testing;
using gi::SamplerKind;

namespace {

class EverySampler : public ::testing::TestWithParam<SamplerKind> {};
INSTANTIATE_TEST_SUITE_P(Kinds, EverySampler,
                         ::testing::Values(SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol),
                         [](const auto& info) { return std::string(info.param == SamplerKind::Sobol ? "Sobol"
                                                                   : gi::sequence_name(info.param)); });

// Pearson's correlation of (x_k, y_k).
double correlation(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / x.size(), my += y[k] / y.size();
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxy += (x[k] - mx) * (y[k] - my);
    sxx += (x[k] - mx) * (x[k] - mx);
    syy += (y[k] - my) * (y[k] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace

TEST(SampleStream, PathDimensionsAreFixedPerDecision) {
  EXPECT_EQ(gi::pixel_dimension, 0u);
  EXPECT_EQ(gi::lens_dimension, 1u);
  EXPECT_EQ(gi::path_dimension(0, gi::Decision::LightChoice), 2u);
  EXPECT_EQ(gi::path_dimension(0, gi::Decision::Roulette), 6u);
  EXPECT_EQ(gi::path_dimension(1, gi::Decision::LightChoice), 7u);
  EXPECT_EQ(gi::path_dimension(3, gi::Decision::BsdfDirection), 2 + 15 + 2u);
}

TEST(SampleStream, NeedsAtLeastOneSamplePerPixel) {
  EXPECT_THROW(gi::make_sample_sequence(SamplerKind::Stratified, 1, 0), std::invalid_argument);
}

TEST_P(EverySampler, AFunctionOfPixelSampleAndDimensionOnly) {
  // The same numbers whatever was asked before and in what order, by get or by next:
  // so any thread can render any pixel's samples, and a path that skips a decision
  // leaves the dimensions of the later ones alone.
  const gi::SampleSequence sampler = gi::make_sample_sequence(GetParam(), 5, 16);
  gi::SampleStream in_order(sampler, 77, 9);
  std::vector<double> first;
  for (int d = 0; d < 8; ++d) {
    const gi::vec2 u = in_order.next_2d();
    first.push_back(u.x);
    first.push_back(u.y);
  }
  const gi::SampleStream other(sampler, 77, 9);
  for (int d = 7; d >= 0; --d) {
    EXPECT_EQ(other.get_2d(d).x, first[2 * d]) << "dimension " << d;
    EXPECT_EQ(other.get_2d(d).y, first[2 * d + 1]) << "dimension " << d;
  }
  gi::SampleStream ones(sampler, 77, 9);
  EXPECT_EQ(ones.next_1d(), other.get_1d(0));
  EXPECT_EQ(ones.next_1d(), other.get_1d(1));
  EXPECT_NE(gi::SampleStream(sampler, 78, 9).get_2d(0).x, first[0]) << "another pixel, other numbers";
  EXPECT_NE(gi::SampleStream(sampler, 77, 10).get_2d(0).x, first[0]) << "another sample, other numbers";
  const gi::SampleSequence reseeded = gi::make_sample_sequence(GetParam(), 6, 16);
  EXPECT_NE(gi::SampleStream(reseeded, 77, 9).get_2d(0).x, first[0]) << "another seed, other numbers";
}

TEST(SampleStream, TheSameBitsOnEveryMachine) {
  // Integer arithmetic to the last step: these values are exact, on every compiler and
  // processor (seed 7, pixel 1234, sample 5 of 64, dimensions 3 and 4). The same bits
  // came out of g++ 12 and clang 14 with libc++ on x86-64, g++ 12 for ARM64 (run under
  // qemu-aarch64) and MinGW-w64 (run under Wine); Sobol's, since its coordinates are
  // scrambled by owen_scramble, from g++ 12 on x86-64, by the same integer arithmetic.
  const std::uint32_t spp = 64;
  const auto values = [&](SamplerKind kind) {
    const gi::SampleSequence sampler = gi::make_sample_sequence(kind, 7, spp);
    const gi::SampleStream s(sampler, 1234, 5);
    const gi::vec2 u = s.get_2d(3);
    return std::vector<double>{u.x, u.y, s.get_1d(4)};
  };
  const std::vector<double> independent = values(SamplerKind::Independent), stratified = values(SamplerKind::Stratified),
                            sobol = values(SamplerKind::Sobol);
  const std::vector<double> expected_independent{0x1.892e14f68c1f8p-3, 0x1.c86ce13b033d8p-1, 0x1.a4d060d5c29ep-2},
      expected_stratified{0x1.1a386897p-3, 0x1.056811908p-1, 0x1.76efd417c8p-1},
      expected_sobol{0x1.b8eb9788p-2, 0x1.cbb68632p-1, 0x1.99abd58ep-1};
  EXPECT_EQ(independent, expected_independent);
  EXPECT_EQ(stratified, expected_stratified);
  EXPECT_EQ(sobol, expected_sobol);
}

TEST(SampleStream, SobolIsANetInEveryDimensionAfterEveryPowerOfTwo) {
  // The first 2^m samples of a pixel, and every later block of 2^m, in every 2D
  // dimension: a (0,m,2)-net. In every 1D dimension: one sample in each interval of 2^-m.
  const gi::SampleSequence sampler = gi::make_sample_sequence(SamplerKind::Sobol, 3, 1);
  for (std::uint64_t pixel : {0ull, 1ull, 99999ull})
    for (std::uint32_t d : {0u, 1u, 2u, 3u, 17u, 400u})
      for (int m = 0; m <= 10; ++m)
        for (std::uint32_t block : {0u, 1u, 5u}) {
          std::vector<t::Point32> points;
          std::vector<int> intervals(std::size_t{1} << m, 0);
          for (std::uint32_t i = block << m; i < (block + 1) << m; ++i) {
            const gi::SampleStream stream(sampler, pixel, i);
            const gi::vec2 u = stream.get_2d(d);
            points.push_back({t::digits_of(u.x), t::digits_of(u.y)});
            ++intervals[std::uint64_t{t::digits_of(stream.get_1d(d))} >> (32 - m)];
          }
          ASSERT_EQ(t::net_defect(points, m), "") << "pixel " << pixel << ", dimension " << d << ", block " << block;
          for (int count : intervals)
            ASSERT_EQ(count, 1) << "1D: pixel " << pixel << ", dimension " << d << ", 2^" << m << " samples";
        }
}

TEST_P(EverySampler, EachNumberAloneIsUniform) {
  // One sample (index 5 of 64) of one dimension, over 20000 pixels: uniform in the square
  // (chi-square on 8 x 8 cells) and in [0, 1) (mean 1/2, variance 1/12).
  const gi::SampleSequence sampler = gi::make_sample_sequence(GetParam(), 11, 64);
  const int pixels = 20000;
  std::vector<gi::vec2> points;
  std::vector<double> x, centred_squares;
  for (int p = 0; p < pixels; ++p) {
    const gi::SampleStream stream(sampler, p, 5);
    points.push_back(stream.get_2d(8));
    x.push_back(stream.get_1d(9));
    centred_squares.push_back((x.back() - 0.5) * (x.back() - 0.5));
  }
  const t::ChiSquare c = t::chi_square_test(t::histogram_2d(points, {0, 0}, {1, 1}, 8, 8),
                                            t::expected_2d([](gi::vec2) { return 1.0; }, {0, 0}, {1, 1}, 8, 8, pixels));
  EXPECT_GT(c.p_value, 1e-6) << "chi-square " << c.statistic;
  const t::Estimate mean = t::estimate(x), variance = t::estimate(centred_squares);
  EXPECT_NEAR(mean.mean, 0.5, 5 * mean.standard_error);
  EXPECT_NEAR(variance.mean, 1.0 / 12, 5 * variance.standard_error);
}

TEST_P(EverySampler, DecisionsOfOneSampleAreIndependent) {
  // Within a pixel, N = 64 samples of two decisions (the 1D dimensions 2 and 3, and the
  // x coordinates of the 2D dimensions 4 and 5): if they walked their strata in step, each
  // pixel's pairs would be strongly correlated. Their correlation r over the 64 samples,
  // squared and averaged over 2000 pixels, must be near that of independent numbers,
  // 1 / (N - 1): measured 0.99 / 63 for independent and stratified samples and 1.6 / 63
  // for Sobol' (whose shuffle keeps samples 2k and 2k + 1 of a pixel a pair: in every
  // dimension one lies in [0, 1/2) and the other in [1/2, 1)), each to about 0.04 / 63.
  // Decisions that walked the sequence in step would give many times more.
  const gi::SampleSequence sampler = gi::make_sample_sequence(GetParam(), 13, 64);
  double sum_r2 = 0, pooled = 0;
  const int pixels = 2000;
  for (int p = 0; p < pixels; ++p) {
    std::vector<double> a, b, c, e;
    for (std::uint32_t i = 0; i < 64; ++i) {
      const gi::SampleStream s(sampler, p, i);
      a.push_back(s.get_1d(2));
      b.push_back(s.get_1d(3));
      c.push_back(s.get_2d(4).x);
      e.push_back(s.get_2d(5).x);
    }
    const double r_ab = correlation(a, b), r_ce = correlation(c, e);
    sum_r2 += r_ab * r_ab + r_ce * r_ce;
    pooled += r_ab + r_ce;
  }
  EXPECT_LT(sum_r2 / (2 * pixels), 2.5 / 63) << "decisions of a pixel's samples move together";
  // The mean r over all pixels: 0 within 5 standard errors (sd of r about 1 / sqrt(63)).
  EXPECT_NEAR(pooled / (2 * pixels), 0.0, 5 / std::sqrt(63.0 * 2 * pixels));
}

TEST_P(EverySampler, NeighbouringPixelsAreIndependent) {
  // The same decision of pixels p and p + 1, sample by sample: uncorrelated, as above.
  const gi::SampleSequence sampler = gi::make_sample_sequence(GetParam(), 17, 64);
  double sum_r2 = 0;
  const int pixels = 2000;
  for (int p = 0; p < pixels; ++p) {
    std::vector<double> a, b;
    for (std::uint32_t i = 0; i < 64; ++i) {
      a.push_back(gi::SampleStream(sampler, p, i).get_2d(0).x);
      b.push_back(gi::SampleStream(sampler, p + 1, i).get_2d(0).x);
    }
    const double r = correlation(a, b);
    sum_r2 += r * r;
  }
  EXPECT_LT(sum_r2 / pixels, 2.5 / 63) << "neighbouring pixels draw alike";
}
