// Graded tests of exercise 4.2: the soft-shadow estimate. One point per test.
// The visibility and the unshadowed light are given as functions, so these tests
// need no ray tracing: they check what your estimate does with them. Where a sample
// lands on the light is your point_on_light's business (exercise 4.1): the
// expectations here are built from your own point_on_light, so a slip there costs
// points in 4.1 only.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/raytrace/soft_shadows.hpp"
#include "support/print.hpp"

using gi::Color;
using gi::vec2;
using gi::vec3;

namespace {

// A 2 x 2 light in the plane y = 3, x and z in [0, 2].
const gi::QuadLight light{{{0, 3, 0}, {0, 0, 2}, {2, 0, 0}, 0}, Color(1)};

const std::vector<vec2> samples = {{0.1, 0.2}, {0.7, 0.3}, {0.4, 0.9}, {0.8, 0.6}};

// Where your point_on_light puts each sample.
std::vector<vec3> points_of(const std::vector<vec2>& uv) {
  std::vector<vec3> points;
  for (const vec2& p : uv) points.push_back(gi::point_on_light(light, p));
  return points;
}

// Tells which sample a point on the light is: the first sample not yet named whose
// point (by your point_on_light) it is, or -1. Naming each sample once keeps them
// apart even where your point_on_light puts several on one point.
class Samples {
 public:
  explicit Samples(const std::vector<vec2>& uv) : points_(points_of(uv)), named_(uv.size(), false) {}
  int which(const vec3& y) {
    for (std::size_t k = 0; k < points_.size(); ++k)
      if (!named_[k] && gi::length(y - points_[k]) < 1e-9) {
        named_[k] = true;
        return static_cast<int>(k);
      }
    return -1;
  }

 private:
  std::vector<vec3> points_;
  std::vector<bool> named_;
};

}  // namespace

TEST(Ex4_2_SoftShadow, UnoccludedLightIsTheMeanOverItsSamples) {
  const std::vector<vec3> points = points_of(samples);
  const auto all = [](const vec3&) { return true; };
  const auto lit = [](const vec3& y) { return Color(y.x, y.z, 1.0); };
  Color expected(0.0);
  for (const vec3& y : points) expected += lit(y) / 4.0;
  const Color got = gi::soft_shadow_estimate(light, samples, all, lit);
  const char* why = gi::length(got - lit(gi::point_on_light(light, {0.5, 0.5}))) < 1e-9
                        ? "this is the light of the light's centre alone: light each sample from its own point, "
                          "point_on_light(light, uv[k]), and average"
                        : "average what a point light at each sample point gives";
  EXPECT_NEAR(got.x, expected.x, 1e-12) << why;
  EXPECT_NEAR(got.y, expected.y, 1e-12) << why;
  EXPECT_NEAR(got.z, 1.0, 1e-12) << "N samples of 1 average to 1: divide the sum by N";
}

TEST(Ex4_2_SoftShadow, HiddenLightGivesNothing) {
  const auto none = [](const vec3&) { return false; };
  const auto lit = [](const vec3&) { return Color(1.0); };
  EXPECT_EQ(gi::soft_shadow_estimate(light, samples, none, lit), Color(0.0))
      << "no shadow ray reaches the light: the point is in the umbra";
}

TEST(Ex4_2_SoftShadow, ShadowRaysGoToTheSamplePoints) {
  const std::vector<vec3> points = points_of(samples);
  std::vector<vec3> asked;
  const auto record = [&](const vec3& y) {
    asked.push_back(y);
    return true;
  };
  gi::soft_shadow_estimate(light, samples, record, [](const vec3&) { return Color(1.0); });
  ASSERT_EQ(asked.size(), samples.size()) << "one visibility test (shadow ray) per sample";
  for (std::size_t k = 0; k < samples.size(); ++k)
    EXPECT_LT(gi::length(asked[k] - points[k]), 1e-9)
        << (gi::length(asked[k] - gi::point_on_light(light, {0.5, 0.5})) < 1e-9
                ? "every shadow ray aims at the light's centre: that is the hard shadow of a point light; aim "
                  "shadow ray k at point_on_light(light, uv[k])"
                : "shadow ray k must aim at point_on_light(light, uv[k]), the point of its own sample");
}

TEST(Ex4_2_SoftShadow, EachSampleIsLitFromItsOwnPoint) {
  const std::vector<vec3> points = points_of(samples);
  std::vector<vec3> shaded;
  const auto record = [&](const vec3& y) {
    shaded.push_back(y);
    return Color(1.0);
  };
  gi::soft_shadow_estimate(light, samples, [](const vec3&) { return true; }, record);
  ASSERT_EQ(shaded.size(), samples.size()) << "ask for the unshadowed light once per visible sample";
  for (std::size_t k = 0; k < samples.size(); ++k)
    EXPECT_LT(gi::length(shaded[k] - points[k]), 1e-9)
        << (gi::length(shaded[k] - gi::point_on_light(light, {0.5, 0.5})) < 1e-9
                ? "every sample is lit from the light's centre: the light from sample k comes from its own point "
                  "on the light, point_on_light(light, uv[k])"
                : "the light from sample k comes from its own point on the light, point_on_light(light, uv[k])");
}

TEST(Ex4_2_SoftShadow, DivideByAllSamplesNotTheVisibleOnes) {
  Samples seen(samples);
  const auto half = [&](const vec3& y) { return seen.which(y) % 2 == 0; };  // samples 0 and 2
  const auto lit = [](const vec3&) { return Color(1.0); };
  EXPECT_NEAR(gi::soft_shadow_estimate(light, samples, half, lit).x, 0.5, 1e-12)
      << "two of four shadow rays reach the light: half lit. Dividing by the visible samples "
         "instead of all N makes every penumbra fully lit";
}

TEST(Ex4_2_SoftShadow, OnlyVisibleSamplesAddLight) {
  Samples seen(samples), shone(samples);
  const auto first_two = [&](const vec3& y) { return seen.which(y) < 2; };
  const auto lit = [&](const vec3& y) { return Color(1.0 + shone.which(y)); };  // 1, 2, 3, 4 for samples 0 to 3
  EXPECT_NEAR(gi::soft_shadow_estimate(light, samples, first_two, lit).x, (1.0 + 2.0) / 4, 1e-12)
      << "add S(x, y_k) I(x, y_k): the light of the visible samples only, each from its own point (here the "
         "bright samples 2 and 3 are hidden, so the mean is not the visible fraction times the mean light)";
}

TEST(Ex4_2_SoftShadow, OneSampleIsAPointLight) {
  const vec3 centre = gi::point_on_light(light, {0.5, 0.5});
  const auto lit = [](const vec3& y) { return Color(y.x, y.y, y.z); };
  const Color got = gi::soft_shadow_estimate(light, {{0.5, 0.5}}, [](const vec3&) { return true; }, lit);
  EXPECT_NEAR(gi::length(got - lit(centre)), 0, 1e-12)
      << "one visible sample: the estimate is the light of a point light at that sample";
}

TEST(Ex4_2_SoftShadow, RandomSamplesEstimateTheVisibleFractionWithoutBias) {
  // The samples with u < 1/2 and v < 1/2, a quarter of the light, are visible; 16
  // random shadow rays per estimate. The estimate is a mean of 16 Bernoulli(1/4)
  // draws, standard deviation sqrt(3/16)/4 = 0.108; the mean of 2000 estimates lies
  // within 4 standard errors (0.0097) of 1/4 except once in about 16 000 seeds, and
  // the seed is fixed.
  gi::Rng rng(41);
  const auto lit = [](const vec3&) { return Color(1.0); };
  double mean = 0, square = 0;
  const int trials = 2000;
  for (int k = 0; k < trials; ++k) {
    const std::vector<vec2> uv = gi::light_samples({gi::LightSampling::Random, 4}, rng);
    Samples seen(uv);
    const auto quarter = [&](const vec3& y) {
      const int i = seen.which(y);
      return i >= 0 && uv[i].x < 0.5 && uv[i].y < 0.5;
    };
    const double e = gi::soft_shadow_estimate(light, uv, quarter, lit).x;
    mean += e / trials, square += e * e / trials;
  }
  const double standard_error = std::sqrt((square - mean * mean) / trials);
  EXPECT_NEAR(mean, 0.25, 4 * standard_error) << "the estimate must be unbiased: the mean over many sample sets "
                                                  "is the visible fraction of the light";
}
