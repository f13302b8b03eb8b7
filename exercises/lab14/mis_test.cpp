// Graded tests of exercises 14.5 and 14.6: the power heuristic, and how much the light a
// BSDF-sampled ray finds counts under each strategy. One point per test.
#include "gi/pathtrace/mis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <utility>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/core/sampling.hpp"
#include "support/print.hpp"
#include "support/statistics.hpp"

TEST(Ex14_5_PowerHeuristic, SquaresTheDensities) {
  EXPECT_NEAR(gi::power_heuristic(1, 3.0, 1, 1.0), 0.9, 1e-12)
      << "w = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2) = 9 / 10 (not the balance heuristic's 3 / 4)";
  EXPECT_NEAR(gi::power_heuristic(1, 1.0, 1, 3.0), 0.1, 1e-12) << "the weight of the less likely strategy";
}

TEST(Ex14_5_PowerHeuristic, CountsTheSamples) {
  EXPECT_NEAR(gi::power_heuristic(2, 1.0, 1, 1.0), 0.8, 1e-12) << "n_f = 2 samples: (2 p)^2 / ((2 p)^2 + p^2)";
  EXPECT_NEAR(gi::power_heuristic(1, 1.0, 3, 1.0), 0.1, 1e-12) << "n_g = 3 samples: p^2 / (p^2 + (3 p)^2) = 1 / 10";
}

TEST(Ex14_5_PowerHeuristic, TheTwoWeightsAddUpToOne) {
  for (double p : {1e-9, 0.2, 1.0, 5.0, 1e7})
    EXPECT_NEAR(gi::power_heuristic(1, p, 1, 0.7) + gi::power_heuristic(1, 0.7, 1, p), 1.0, 1e-12)
        << "w_f + w_g must be 1 wherever either strategy can sample, or light is lost or doubled";
  EXPECT_NEAR(gi::power_heuristic(1, 2.0, 1, 0.0), 1.0, 1e-12) << "when only f can sample, f takes it all";
}

TEST(Ex14_5_PowerHeuristic, NotANumberIsZero) {
  EXPECT_EQ(gi::power_heuristic(1, 0.0, 1, 0.0), 0.0) << "0 / 0 is not a weight: return 0 when w is not finite";
  EXPECT_EQ(gi::power_heuristic(1, INFINITY, 1, 1.0), 0.0) << "inf / inf is not a weight: return 0";
}

TEST(Ex14_6_BsdfWeight, AloneBsdfSamplingCountsAllItFinds) {
  EXPECT_EQ(gi::bsdf_sample_weight(gi::Strategy::Bsdf, 0.3, 20.0), 1.0)
      << "with BSDF sampling alone, the emission a ray runs into is the only estimate of that light: weight 1";
}

TEST(Ex14_6_BsdfWeight, WithLightSamplingItCountsNothing) {
  EXPECT_EQ(gi::bsdf_sample_weight(gi::Strategy::Lights, 0.3, 20.0), 0.0)
      << "under Lights the shadow ray already brought this light in: counting it again doubles the direct light";
}

TEST(Ex14_6_BsdfWeight, WithMisItIsThePowerHeuristicOfTheBsdfsDensity) {
  // Measured against your own power heuristic (exercise 14.5), so that a bug there is
  // charged to 14.5 alone.
  EXPECT_NEAR(gi::bsdf_sample_weight(gi::Strategy::Mis, 3.0, 1.0), gi::power_heuristic(1, 3.0, 1, 1.0), 1e-12)
      << "w_bsdf = power_heuristic(1, p_bsdf, 1, p_light): the BSDF sampled this ray, so p_bsdf comes first";
  EXPECT_NEAR(
      gi::bsdf_sample_weight(gi::Strategy::Mis, 3.0, 1.0) + gi::light_sample_weight(gi::Strategy::Mis, 1.0, 3.0), 1.0,
      1e-12)
      << "w_bsdf + w_light must be 1 for the same light path";
}

namespace {

// The direct light at a point of a floor of reflectance rho under a dome of radius 1
// that emits L_e = 1 everywhere, estimated the way the path tracer does it -- one light
// sample and one BSDF sample, each weighted by its strategy -- but with the sampling
// written here, so that this test runs on your weights alone and a bug in exercises
// 14.1 to 14.4 costs points there only. Whatever the strategy, E[estimate] = rho L_e.
double direct_under_a_dome(gi::Strategy strategy, double rho, gi::Rng& rng) {
  // The light sample: a uniform point of the dome (area 2 pi), seen from its centre
  // at distance 1 and straight on: p_light = 1 / (2 pi) per steradian. The BSDF would
  // have drawn the same direction with p = cos / pi.
  const double cos_l = rng.uniform(), p_light = 1 / (2 * gi::pi);
  const double light =
      gi::light_sample_weight(strategy, p_light, cos_l / gi::pi) * (rho / gi::pi) * cos_l / p_light;
  // The BSDF sample: a cosine-weighted direction (Malley: cos = sqrt(1 - u)), which
  // runs into the dome; the light sampler would have drawn it with p = 1 / (2 pi).
  const double cos_b = std::sqrt(1 - rng.uniform()), p_bsdf = cos_b / gi::pi;
  const double bsdf = gi::bsdf_sample_weight(strategy, p_bsdf, p_light) * (rho / gi::pi) * cos_b / p_bsdf;
  return light + bsdf;
}

// Does your power heuristic give weights that add up to 1 (exercise 14.5's own test)?
// MIS is checked here only then, so that a bug there is not charged to 14.6 as well.
bool heuristic_adds_up() {
  for (const auto& [a, b] : {std::pair{0.3, 0.16}, {2.0, 0.5}, {0.01, 0.2}})
    if (std::abs(gi::power_heuristic(1, a, 1, b) + gi::power_heuristic(1, b, 1, a) - 1) > 1e-9) return false;
  return true;
}

}  // namespace

TEST(Ex14_6_BsdfWeight, UnderAGlowingDomeDirectLightIsCountedOnce) {
  // 10 seeds of 4096 sample pairs, 6 standard errors: a false failure about once in
  // 10^4 runs. BSDF sampling alone has no variance here (every ray finds L_e = 1).
  const double rho = 0.5;
  std::vector<gi::Strategy> strategies = {gi::Strategy::Bsdf, gi::Strategy::Lights};
  if (heuristic_adds_up()) strategies.push_back(gi::Strategy::Mis);
  for (const gi::Strategy strategy : strategies) {
    std::vector<double> means;
    for (int seed = 1; seed <= 10; ++seed) {
      gi::Rng rng(seed, 14);
      double sum = 0;
      for (int k = 0; k < 4096; ++k) sum += direct_under_a_dome(strategy, rho, rng);
      means.push_back(sum / 4096);
    }
    const gi::testing::Estimate e = gi::testing::estimate(means);
    EXPECT_NEAR(e.mean, rho, 6 * e.standard_error + 1e-9)
        << gi::name(strategy) << ": the direct light under a dome of L_e = 1 is " << e.mean << " instead of rho = "
        << rho << " -- "
        << (e.mean > 1.25 * rho ? "the light found by the BSDF ray is counted on top of the light sample"
                                : "the weights of the two strategies do not add up to 1 for the same light path");
  }
}
