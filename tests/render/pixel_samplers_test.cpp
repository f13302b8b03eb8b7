#include "gi/render/pixel_samplers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gi/render/adaptive.hpp"
#include "support/statistics.hpp"

using gi::Color;
using gi::vec2;

namespace {

// How likely a uniform sampler gives positions this unevenly spread over a bins x bins
// grid of the unit square (the shared chi-square test, tests/support/statistics.hpp).
double uniformity(const std::vector<vec2>& points, int bins) {
  namespace t = gi::testing;
  return t::chi_square_test(t::histogram_2d(points, {0, 0}, {1, 1}, bins, bins),
                            t::expected_2d([](vec2) { return 1.0; }, {0, 0}, {1, 1}, bins, bins, double(points.size())))
      .p_value;
}

// Coverage of the half-plane y < 0.37 + 0.61 x in the unit square, the pixel value
// at an edge; exact: 0.37 + 0.61 / 2.
double coverage(const std::vector<vec2>& points) {
  double inside = 0;
  for (const vec2& p : points) inside += p.y < 0.37 + 0.61 * p.x;
  return inside / points.size();
}

}  // namespace

TEST(PixelSamplers, GridIsTheCellCentres) {
  const std::vector<vec2> g = gi::grid_positions(2);
  ASSERT_EQ(g.size(), 4u);
  EXPECT_EQ(g[0], vec2(0.25, 0.25));
  EXPECT_EQ(g[3], vec2(0.75, 0.75));
  EXPECT_EQ(gi::grid_positions(1)[0], vec2(0.5, 0.5));
}

TEST(PixelSamplers, RandomAndJitteredAreUniform) {
  // 100 bins, chi-square at p = 0.001: a uniform sampler fails one seed in a thousand.
  gi::Rng rng(3);
  std::vector<vec2> random;
  gi::random_positions(20000, rng, random);
  EXPECT_GT(uniformity(random, 10), 0.001);
  std::vector<vec2> jittered;
  for (int k = 0; k < 1250; ++k)
    for (const vec2& p : gi::jittered_positions(4, rng)) jittered.push_back(p);
  EXPECT_GT(uniformity(jittered, 10), 0.001);
}

TEST(PixelSamplers, JitteringHasLessVarianceThanRandomAtAnEdge) {
  // Both estimators are unbiased for the covered area; stratification cuts the
  // variance at an edge from O(1/N) to about O(N^-1.5).
  const double exact = 0.37 + 0.61 / 2;
  gi::Rng rng(4);
  double mean_random = 0, mean_jittered = 0, var_random = 0, var_jittered = 0;
  const int trials = 4000;
  for (int k = 0; k < trials; ++k) {
    std::vector<vec2> random;
    gi::random_positions(16, rng, random);
    const double r = coverage(random) - exact;
    const double j = coverage(gi::jittered_positions(4, rng)) - exact;
    mean_random += r / trials, mean_jittered += j / trials;
    var_random += r * r / trials, var_jittered += j * j / trials;
  }
  EXPECT_NEAR(mean_random, 0.0, 4 * std::sqrt(var_random / trials));
  EXPECT_NEAR(mean_jittered, 0.0, 4 * std::sqrt(var_jittered / trials));
  EXPECT_NEAR(var_random, exact * (1 - exact) / 16, 0.1 * exact * (1 - exact) / 16);  // binomial
  EXPECT_LT(var_jittered, 0.3 * var_random);
}

TEST(PixelSamplers, AdaptiveSpendsFourSamplesOnFlatPixels) {
  const gi::AdaptiveSample flat = gi::adaptive_sample([](vec2) { return Color(0.7); }, 0.01, 3);
  EXPECT_EQ(flat.samples, 4);
  EXPECT_EQ(flat.colour, Color(0.7));
}

TEST(PixelSamplers, AdaptiveRefinesTowardsTheEdgeArea) {
  // Deeper subdivision converges on the covered fraction of a diagonal edge; every
  // level adds 5 samples per split square.
  const auto edge = [](vec2 p) { return Color(p.y < 0.37 + 0.61 * p.x ? 1.0 : 0.0); };
  double previous_error = 1;
  int previous_samples = 0;
  for (int levels = 1; levels <= 6; ++levels) {
    const gi::AdaptiveSample a = gi::adaptive_sample(edge, 0.01, levels);
    EXPECT_EQ((a.samples - 4) % 5, 0);
    EXPECT_GT(a.samples, previous_samples);
    const double error = std::abs(a.colour.x - (0.37 + 0.61 / 2));
    EXPECT_LE(error, previous_error + 1e-12) << levels;
    previous_error = error, previous_samples = a.samples;
  }
  EXPECT_LT(previous_error, 0.01);
  EXPECT_LT(previous_samples, 4 + 5 * (1 + 4 + 16 + 64 + 256 + 1024) / 4);  // only squares on the edge split
}

TEST(PixelSamplers, NamesAndChecks) {
  for (const std::string& name : gi::sampler_names()) EXPECT_EQ(gi::sampler_name(gi::sampler_from_name(name)), name);
  EXPECT_THROW(gi::sampler_from_name("stochastic"), std::invalid_argument);
  EXPECT_THROW(gi::check(gi::Sampling{gi::Sampler::Grid, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(gi::Sampling{gi::Sampler::Adaptive, 1, NAN}), std::invalid_argument);
  EXPECT_THROW(gi::check(gi::Sampling{gi::Sampler::Adaptive, 1, 0.1, 9}), std::invalid_argument);
  EXPECT_NO_THROW(gi::check(gi::Sampling{gi::Sampler::Jittered, 64}));
}
