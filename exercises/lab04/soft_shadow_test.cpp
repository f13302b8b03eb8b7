// Graded tests of exercise 4.2: the soft-shadow estimate. One point per test.
// The visibility and the unshadowed light are given as functions, so these tests
// need no ray tracing: they check what your estimate does with them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/raytrace/soft_shadows.hpp"

using gi::Color;
using gi::vec2;
using gi::vec3;

namespace {

// A 2 x 2 light in the plane y = 3, x and z in [0, 2].
const gi::QuadLight light{{{0, 3, 0}, {0, 0, 2}, {2, 0, 0}, 0}, Color(1)};

vec3 on_light(vec2 uv) { return vec3(0, 3, 0) + uv.x * vec3(0, 0, 2) + uv.y * vec3(2, 0, 0); }

const std::vector<vec2> samples = {{0.1, 0.2}, {0.7, 0.3}, {0.4, 0.9}, {0.8, 0.6}};

bool same_point(const vec3& a, const vec3& b) { return gi::length(a - b) < 1e-9; }

}  // namespace

TEST(Ex4_2_SoftShadow, UnoccludedLightIsTheMeanOverItsSamples) {
  const auto all = [](const vec3&) { return true; };
  const auto lit = [](const vec3& y) { return Color(y.x, y.z, 1.0); };
  Color expected(0.0);
  for (const vec2& uv : samples) expected += lit(on_light(uv)) / 4.0;
  const Color got = gi::soft_shadow_estimate(light, samples, all, lit);
  EXPECT_NEAR(got.x, expected.x, 1e-12) << "average what a point light at each sample point gives";
  EXPECT_NEAR(got.y, expected.y, 1e-12) << "average what a point light at each sample point gives";
  EXPECT_NEAR(got.z, 1.0, 1e-12) << "N samples of 1 average to 1: divide the sum by N";
}

TEST(Ex4_2_SoftShadow, HiddenLightGivesNothing) {
  const auto none = [](const vec3&) { return false; };
  const auto lit = [](const vec3&) { return Color(1.0); };
  EXPECT_EQ(gi::soft_shadow_estimate(light, samples, none, lit), Color(0.0))
      << "no shadow ray reaches the light: the point is in the umbra";
}

TEST(Ex4_2_SoftShadow, DivideByAllSamplesNotTheVisibleOnes) {
  const auto half = [](const vec3& y) { return y.z < 1.0; };  // samples 1 and 3 (u < 0.5)
  const auto lit = [](const vec3&) { return Color(1.0); };
  EXPECT_NEAR(gi::soft_shadow_estimate(light, samples, half, lit).x, 0.5, 1e-12)
      << "two of four shadow rays reach the light: half lit. Dividing by the visible samples "
         "instead of all N makes every penumbra fully lit";
}

TEST(Ex4_2_SoftShadow, ShadowRaysGoToTheSamplePoints) {
  std::vector<vec3> asked;
  const auto record = [&](const vec3& y) {
    asked.push_back(y);
    return true;
  };
  gi::soft_shadow_estimate(light, samples, record, [](const vec3&) { return Color(1.0); });
  ASSERT_EQ(asked.size(), samples.size()) << "one visibility test (shadow ray) per sample";
  for (std::size_t k = 0; k < samples.size(); ++k)
    EXPECT_TRUE(same_point(asked[k], on_light(samples[k])))
        << "shadow ray " << k << " must aim at point_on_light(light, uv[" << k << "]); aiming every ray at the "
        << "centre gives the hard shadow of a point light";
}

TEST(Ex4_2_SoftShadow, EachSampleIsLitFromItsOwnPoint) {
  std::vector<vec3> shaded;
  const auto record = [&](const vec3& y) {
    shaded.push_back(y);
    return Color(1.0);
  };
  gi::soft_shadow_estimate(light, samples, [](const vec3&) { return true; }, record);
  ASSERT_EQ(shaded.size(), samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k)
    EXPECT_TRUE(same_point(shaded[k], on_light(samples[k])))
        << "the light from sample " << k << " comes from its own point on the light, not the centre";
}

TEST(Ex4_2_SoftShadow, OnlyVisibleSamplesAddLight) {
  const auto left = [](const vec3& y) { return y.x < 1.0; };  // samples 0 and 1 (v < 0.5)
  const auto lit = [](const vec3& y) { return Color(1.0 + y.x); };
  const double expected = ((1.0 + on_light(samples[0]).x) + (1.0 + on_light(samples[1]).x)) / 4.0;
  EXPECT_NEAR(gi::soft_shadow_estimate(light, samples, left, lit).x, expected, 1e-12)
      << "add S(x, y_k) I(x, y_k): the light of the visible samples only";
}

TEST(Ex4_2_SoftShadow, OneSampleAtTheCentreIsAPointLight) {
  const auto lit = [](const vec3& y) { return Color(y.x, y.y, y.z); };
  const Color got = gi::soft_shadow_estimate(light, {{0.5, 0.5}}, [](const vec3&) { return true; }, lit);
  EXPECT_NEAR(got.x, 1.0, 1e-12);
  EXPECT_NEAR(got.y, 3.0, 1e-12);
  EXPECT_NEAR(got.z, 1.0, 1e-12) << "one sample at the centre: the point light at (1, 3, 1)";
}

TEST(Ex4_2_SoftShadow, RandomSamplesEstimateTheVisibleFractionWithoutBias) {
  // A quarter of the light (x < 1 and z < 1) is visible; 16 random shadow rays per
  // estimate. The mean of 2000 estimates lies within 4 standard errors of 1/4.
  gi::Rng rng(41);
  const auto quarter = [](const vec3& y) { return y.x < 1.0 && y.z < 1.0; };
  const auto lit = [](const vec3&) { return Color(1.0); };
  double mean = 0, square = 0;
  const int trials = 2000;
  for (int k = 0; k < trials; ++k) {
    const double e = gi::soft_shadow_estimate(light, gi::light_samples({gi::LightSampling::Random, 4}, rng), quarter, lit).x;
    mean += e / trials, square += e * e / trials;
  }
  const double standard_error = std::sqrt((square - mean * mean) / trials);
  EXPECT_NEAR(mean, 0.25, 4 * standard_error) << "the estimate must be unbiased: the mean over many sample sets "
                                                  "is the visible fraction of the light";
}
