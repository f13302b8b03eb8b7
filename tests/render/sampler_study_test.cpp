// The samplers at work: every estimator of the study unbiased with every sampler, and
// the error falling at the rate the theory gives each sampler (sampler_study.hpp).
//
// Statistical tests: the unbiasedness test's 24 means each fail by chance with
// probability about 6e-7 (5 standard errors); the slopes are fitted to within a
// standard error of about 0.01 and tested against bands 0.1 to 0.2 wide around the
// theory, which a sampler whose stratification or scramble is broken falls out of
// (independent samples give -1/2 everywhere, a shifted net -1 on smooth integrands).
#include "gi/render/sampler_study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/statistics.hpp"

namespace t = gi::testing;
using gi::SamplerKind;

namespace {

const std::vector<SamplerKind> every_sampler{SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol};

}  // namespace

TEST(SamplerStudy, SquareLightFormFactorByHand) {
  // A square of side 2h centred at height h: A = B = 1, F = (4 / 2 pi) 2 (1/sqrt 2) atan(1/sqrt 2).
  EXPECT_NEAR(gi::form_factor_point_to_centred_square(2, 1), 4 / gi::pi * std::atan(1 / std::sqrt(2.0)) / std::sqrt(2.0),
              1e-15);
  EXPECT_NEAR(gi::form_factor_point_to_centred_square(1e6, 1), 1.0, 1e-5) << "an infinite plane fills the sky";
  EXPECT_NEAR(gi::form_factor_point_to_centred_square(1e-3, 1), 1e-6 / gi::pi, 1e-12) << "far away: A cos^2 / (pi d^2)";
}

TEST(SamplerStudy, EveryEstimatorIsUnbiasedWithEverySampler) {
  // The mean of 4000 pixels' estimates (16 and 64 samples each) against the closed form.
  for (const gi::Estimator& e : gi::study_estimators())
    for (SamplerKind kind : every_sampler)
      for (std::uint32_t n : {16u, 64u}) {
        const t::Estimate m = t::estimate(gi::pixel_estimates(e, kind, 2718 + n, n, 4000, 0));
        EXPECT_NEAR(m.mean, e.exact, 5 * m.standard_error)
            << e.name << ", " << gi::sequence_name(kind) << ", " << n << " samples: standard error " << m.standard_error;
      }
}

TEST(SamplerStudy, ErrorFallsAtTheRateOfEachSampler) {
  gi::StudySettings settings;
  settings.sample_counts = {4, 16, 64, 256, 1024};
  settings.pixels = 256;
  const gi::SamplerStudy study = gi::sampler_study(gi::study_estimators(), every_sampler, settings, 0);
  ASSERT_EQ(study.slopes.size(), 12u);
  ASSERT_EQ(study.rows.size(), 60u);
  for (const gi::StudySlope& s : study.slopes) {
    const std::string what = s.estimator + ", " + gi::sequence_name(s.sampler);
    EXPECT_LT(s.standard_error, 0.03) << what << ": too few pixels to tell the slopes apart";
    if (s.sampler == SamplerKind::Independent) {
      EXPECT_NEAR(s.slope, -0.5, 0.07) << what << ": independent samples converge as N^-1/2";
    } else if (s.expected == -0.75) {  // a jump
      EXPECT_GT(s.slope, -0.9) << what;
      EXPECT_LT(s.slope, -0.6) << what << ": a well-spread sampler beats N^-1/2 even across a jump (N^-3/4)";
    } else if (s.sampler == SamplerKind::Stratified) {
      EXPECT_NEAR(s.slope, -1.0, 0.1) << what << ": n x n strata on a smooth integrand give N^-1";
    } else {
      EXPECT_GT(s.slope, -1.7) << what;
      EXPECT_LT(s.slope, -1.3) << what << ": Owen's scramble gives about N^-3/2 on a smooth integrand (a shifted net "
                                          "only N^-1)";
    }
  }
}

TEST(SamplerStudy, TheSameNumbersOnAnyNumberOfThreads) {
  gi::StudySettings settings;
  settings.sample_counts = {4, 16};
  settings.pixels = 50;
  const auto one = gi::sampler_study(gi::study_estimators(), every_sampler, settings, 1);
  const auto three = gi::sampler_study(gi::study_estimators(), every_sampler, settings, 3);
  for (std::size_t k = 0; k < one.rows.size(); ++k) EXPECT_EQ(one.rows[k].rms, three.rows[k].rms);
}

TEST(SamplerStudy, RefusesWhatItCannotFit) {
  gi::StudySettings settings;
  settings.pixels = 1;
  EXPECT_THROW(gi::sampler_study(gi::study_estimators(), every_sampler, settings, 1), std::invalid_argument);
  settings.pixels = 16385;  // a film's width at most
  EXPECT_THROW(gi::sampler_study(gi::study_estimators(), every_sampler, settings, 1), std::invalid_argument);
  settings.pixels = 10;
  settings.sample_counts = {16};
  EXPECT_THROW(gi::sampler_study(gi::study_estimators(), every_sampler, settings, 1), std::invalid_argument);
  settings.sample_counts = {0, 16};
  EXPECT_THROW(gi::sampler_study(gi::study_estimators(), every_sampler, settings, 1), std::invalid_argument);
  EXPECT_THROW(gi::fit_log_log_slope({{4, 0.1, 0.01}}), std::invalid_argument);
  EXPECT_THROW(gi::fit_log_log_slope({{4, 0.1, 0.01}, {16, 0.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(gi::fit_log_log_slope({{4, 0.1, 0.01}, {4, 0.2, 0.01}}), std::invalid_argument);
}

TEST(FitLogLogSlope, ALawFoundExactly) {
  // e = 3 N^-3/4 exactly, each point known to 1%: slope -3/4, and the standard error
  // sqrt(sum dx^2 0.01^2) / S = 0.01 / sqrt(S).
  std::vector<gi::LogLogPoint> points;
  double sxx = 0, mean = (std::log(4.0) + std::log(16.0) + std::log(64.0)) / 3;
  for (double n : {4.0, 16.0, 64.0}) {
    points.push_back({n, 3 * std::pow(n, -0.75), 0.03 * std::pow(n, -0.75)});
    sxx += (std::log(n) - mean) * (std::log(n) - mean);
  }
  const gi::Slope s = gi::fit_log_log_slope(points);
  EXPECT_NEAR(s.slope, -0.75, 1e-12);
  EXPECT_NEAR(s.standard_error, 0.01 / std::sqrt(sxx), 1e-12);
}
