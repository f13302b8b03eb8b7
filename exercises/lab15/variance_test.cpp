// Graded tests of exercise 15.1: path tracing's variance v from measured errors,
// e^2 = v / N + r^2. One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/pathtrace/convergence.hpp"
#include "support/print.hpp"

namespace {

// The law exactly: e = sqrt(v / N + r^2).
gi::ErrorAtSamples on_law(double v, double r, double spp) { return {spp, std::sqrt(v / spp + r * r)}; }

}  // namespace

TEST(Ex15_1_MonteCarloVariance, OnePointWithAPerfectReference) {
  // r = 0: e^2 = v / N, so v = N e^2 = 4 x 0.1^2 = 0.04.
  const double v = gi::monte_carlo_variance({{4, 0.1}}, 0);
  const auto near = [&](double x) { return std::abs(v - x) < 1e-12; };
  EXPECT_NEAR(v, 0.04, 1e-12)
      << (!std::isfinite(v)
              ? "one point, N = 4 and e = 0.1, gives v = N e^2 = 0.04 on its own, but you got v = " +
                    testing::PrintToString(v) + ": v is the plain mean of the v_k, their sum divided by the number "
                    "of points n, not by n - 1 as for a sample variance (here n - 1 = 0)"
              : "the squared error falls as 1/N: v = N e^2 = 4 x 0.1^2 = 0.04, got " + testing::PrintToString(v) +
                    (near(0.4)    ? " = N e: square the error"
                     : near(0.02) ? " = sqrt(N) e^2: it is the error that falls as 1/sqrt(N), its square as 1/N"
                                  : std::string(" (not N e, not sqrt(N) e^2)")));
}

TEST(Ex15_1_MonteCarloVariance, PointsOnTheLawGiveItsV) {
  std::vector<gi::ErrorAtSamples> points;
  for (double spp : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0}) points.push_back(on_law(0.03, 0.001, spp));
  EXPECT_NEAR(gi::monte_carlo_variance(points, 0.001), 0.03, 1e-9)
      << "errors exactly on e^2 = v/N + r^2 (v = 0.03, r = 0.001) must give v back: v_k = N_k (e_k^2 - r^2)";
}

TEST(Ex15_1_MonteCarloVariance, SubtractsTheReferencesOwnError) {
  // A reference as noisy as the pictures: at 64 spp e^2 = 0.01/64 + 0.05^2 is almost all
  // the reference's. Left in, it grows N e^2 with N and makes v ten times too large.
  std::vector<gi::ErrorAtSamples> points;
  for (double spp : {1.0, 4.0, 16.0, 64.0}) points.push_back(on_law(0.01, 0.05, spp));
  const double v = gi::monte_carlo_variance(points, 0.05);
  EXPECT_NEAR(v, 0.01, 1e-9) << "the reference's own squared error r^2 is in every e^2 and does not fall with N: "
                                "subtract it, v_k = N_k (e_k^2 - r^2) (got v = "
                             << v << ")";
}

TEST(Ex15_1_MonteCarloVariance, AveragesEveryPoint) {
  // Two noisy points: v_1 = 1 x (0.2^2) = 0.04 and v_2 = 16 x (0.04^2) = 0.0256.
  const double v = gi::monte_carlo_variance({{1, 0.2}, {16, 0.04}}, 0);
  EXPECT_NEAR(v, (0.04 + 0.0256) / 2, 1e-12)
      << "each point gives its own estimate v_k = N_k e_k^2; v is their mean over all the points (got " << v << ")";
}

TEST(Ex15_1_MonteCarloVariance, KeepsPointsThatLandBelowTheReferencesError) {
  // The second picture happened to land closer than the reference's own error: its v_k
  // is negative, -100 x 0.0001 = -0.01, and it must count, or v is biased upwards.
  const double r = 0.03;
  const double v = gi::monte_carlo_variance({{1, std::sqrt(0.02 + r * r)}, {100, std::sqrt(r * r - 0.0001)}}, r);
  EXPECT_NEAR(v, (0.02 - 0.01) / 2, 1e-12)
      << "a negative v_k is an honest estimate (noise), not an error: dropping it or clamping it at 0 biases v up";
}

TEST(Ex15_1_MonteCarloVariance, UnbiasedOnSimulatedPictures) {
  // A picture of 300 blocks: block b's truth is t_b, one sample of it t_b + s_b (u - 1/2)
  // with u uniform, so a sample's variance is s_b^2 / 12. The reference is the truth plus
  // noise of standard deviation q_b (known, as a reference's standard error is), the
  // picture the mean of N samples. Error measure: relative RMS, sqrt(sum (x - ref)^2 /
  // sum ref^2). Then v = sum s_b^2/12 / sum t_b^2 and r^2 = sum q_b^2 / sum t_b^2 (to
  // within the reference's noise in the denominator, < 0.1%). 40 seeds; the mean of v
  // must lie within 5 standard errors of the truth: a false failure about once in 10^6.
  const int blocks = 300, seeds = 40;
  std::vector<double> t(blocks), s(blocks), q(blocks);
  double sum_t2 = 0, sum_var = 0, sum_q2 = 0;
  for (int b = 0; b < blocks; ++b) {
    t[b] = 1 + b % 7, s[b] = 0.5 * t[b], q[b] = 0.004 * t[b];
    sum_t2 += t[b] * t[b], sum_var += s[b] * s[b] / 12, sum_q2 += q[b] * q[b];
  }
  const double v_true = sum_var / sum_t2;
  std::vector<double> fitted;
  for (int seed = 0; seed < seeds; ++seed) {
    gi::Rng rng(1515, seed);
    std::vector<double> ref(blocks), sum(blocks, 0.0);
    double sum_ref2 = 0;
    for (int b = 0; b < blocks; ++b) {
      // A normal deviate for the reference's noise (Box-Muller).
      const double z = std::sqrt(-2 * std::log(1 - rng.uniform())) * std::cos(2 * gi::pi * rng.uniform());
      ref[b] = t[b] + q[b] * z, sum_ref2 += ref[b] * ref[b];
    }
    std::vector<gi::ErrorAtSamples> points;
    int n = 0;
    for (int spp = 1; spp <= 256; spp *= 4) {
      for (; n < spp; ++n)
        for (int b = 0; b < blocks; ++b) sum[b] += t[b] + s[b] * (rng.uniform() - 0.5);
      double squared = 0;
      for (int b = 0; b < blocks; ++b) squared += (sum[b] / n - ref[b]) * (sum[b] / n - ref[b]);
      points.push_back({double(spp), std::sqrt(squared / sum_ref2)});
    }
    fitted.push_back(gi::monte_carlo_variance(points, std::sqrt(sum_q2 / sum_t2)));
  }
  double mean = 0, spread = 0;
  for (double v : fitted) mean += v / seeds;
  for (double v : fitted) spread += (v - mean) * (v - mean) / (seeds - 1);
  const double standard_error = std::sqrt(spread / seeds);
  EXPECT_NEAR(mean, v_true, 5 * standard_error + 1e-3 * v_true)
      << "over " << seeds << " simulated pictures the fitted v averages " << mean << " against the true " << v_true
      << ": each v_k = N_k (e_k^2 - r^2) is unbiased, and so is their plain mean; anything else (e instead of e^2, "
         "r^2 left in, negative v_k dropped) is not";
}
