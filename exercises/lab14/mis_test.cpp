// Graded tests of exercises 14.5 and 14.6: the power heuristic, and how much the light a
// BSDF-sampled ray finds counts under each strategy. One point per test.
#include "gi/pathtrace/mis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gi/core/sampling.hpp"
#include "gi/pathtrace/path_trace.hpp"
#include "gi/pathtrace/next_event.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/roulette.hpp"
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

// What the furnace needs of exercises 14.1-14.5, as a message ("" when all is well): it
// renders with the whole lab, so a bug in an earlier exercise is named as that, not as
// one of the weights.
std::string earlier_exercise_problem() {
  const std::string fix = ": the furnace renders with it -- make that exercise's tests pass first";
  const gi::vec3 w = gi::sample_cosine_hemisphere({0.64, 0.25});
  if (std::abs(w.x) > 1e-9 || std::abs(w.y - 0.8) > 1e-9 || std::abs(w.z - 0.6) > 1e-9)
    return "your cosine sampler (exercise 14.1) maps u = (0.64, 0.25) elsewhere than (0, 0.8, 0.6)" + fix;
  if (std::abs(gi::cosine_hemisphere_pdf(0.6) - 0.6 / gi::pi) > 1e-12 || gi::cosine_hemisphere_pdf(-0.5) != 0)
    return "your cosine density (exercise 14.2) is not cos / pi above the horizon and 0 below" + fix;
  gi::Color beta(0.2, 0.1, 0.1);
  if (!gi::russian_roulette(beta, 0.1) || std::abs(beta.x - 1) > 1e-12)
    return "your roulette (exercise 14.3) does not go on with probability q and carry beta / q" + fix;
  const gi::Bsdf white{gi::BsdfKind::Lambertian, gi::Color(1.0), 1.0};
  const gi::LightSample y{{0, 0, 2}, {0, 0, -1}, gi::Color(1.0), 0.5, 0};
  const gi::DirectSample d = gi::next_event_estimate(white, {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, y);
  if (std::abs(d.p_light - 2.0) > 1e-9 || std::abs(d.estimate.x - 0.5 / gi::pi) > 1e-9)
    return "your next-event estimate (exercise 14.4) is wrong for a light straight above" + fix;
  if (std::abs(gi::power_heuristic(1, 3.0, 1, 1.0) - 0.9) > 1e-12 || gi::power_heuristic(1, 0.0, 1, 0.0) != 0)
    return "your power heuristic (exercise 14.5) is not (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)" + fix;
  return "";
}

}  // namespace

TEST(Ex14_6_BsdfWeight, TheFurnaceCountsDirectLightOnce) {
  const std::string problem = earlier_exercise_problem();
  ASSERT_TRUE(problem.empty()) << problem;
  // This test renders with your whole lab 14. The white furnace (rho = 0.5, L_e = 1 on
  // every wall) with paths of one bounce: L = L_e (1 + rho) = 1.5 everywhere. Counting the
  // direct light twice gives 2. 10 seeds, 6 standard errors: a false failure about once
  // in 10^4 runs.
  const gi::PathScene furnace = gi::make_path_scene(gi::furnace_scene(0.5, 1.0));
  for (const gi::Strategy strategy : {gi::Strategy::Lights, gi::Strategy::Mis}) {
    gi::PathSettings settings;
    settings.strategy = strategy;
    settings.max_depth = 1;
    std::vector<double> means;
    for (int seed = 1; seed <= 10; ++seed) {
      gi::Film film = gi::make_film(8, 8, seed);
      gi::path_trace(film, furnace, settings, 16, 1);
      double sum = 0;
      for (const gi::Pixel& p : gi::film_mean(film).pixels) sum += p.x;
      means.push_back(sum / 64);
    }
    const gi::testing::Estimate e = gi::testing::estimate(means);
    EXPECT_NEAR(e.mean, 1.5, 6 * e.standard_error + 1e-6)
        << gi::name(strategy) << ": the furnace's direct light is " << e.mean - 1 << " instead of 0.5 -- "
        << (e.mean > 1.75 ? "the light found by the BSDF ray is counted on top of the light sample"
                          : "the weights of the two strategies do not add up to 1");
  }
}
