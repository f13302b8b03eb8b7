// Graded tests of exercise 15.2: the samples per pixel an error costs path tracing,
// N = v / (e^2 - r^2). One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/pathtrace/convergence.hpp"
#include "support/print.hpp"

TEST(Ex15_2_SamplesForError, APerfectReference) {
  // r = 0: e^2 = v / N, so N = v / e^2 = 0.03 / 0.01^2 = 300.
  const auto n = gi::samples_for_error(0.03, 0.01, 0);
  ASSERT_TRUE(n) << "an error above the reference's (here 0) can always be reached: return a number";
  EXPECT_NEAR(*n, 300, 1e-9) << "the squared error falls as 1/N: N = v / e^2 (halving the error costs 4x the samples)";
}

TEST(Ex15_2_SamplesForError, SubtractsTheSquaresNotTheErrors) {
  // v = 0.03, r = 0.006, e = 0.01: N = 0.03 / (1e-4 - 3.6e-5) = 468.75.
  const auto n = gi::samples_for_error(0.03, 0.01, 0.006);
  ASSERT_TRUE(n) << "e = 0.01 > r = 0.006: reachable";
  EXPECT_NEAR(*n, 468.75, 1e-6) << "the reference's noise adds in squares, e^2 = v/N + r^2: N = v / (e^2 - r^2), "
                                   "not v / e^2 (300) or v / (e - r)^2 (1875)";
}

TEST(Ex15_2_SamplesForError, NothingAtOrBelowTheReferencesError) {
  EXPECT_FALSE(gi::samples_for_error(0.03, 0.005, 0.005))
      << "e = r: only infinitely many samples reach the reference's own error; say so with nothing";
  EXPECT_FALSE(gi::samples_for_error(0.03, 0.004, 0.005))
      << "e < r: no picture can be shown closer to the truth than the reference it is measured against";
  EXPECT_FALSE(gi::samples_for_error(0.03, 0, 0)) << "e = 0 with a perfect reference: no finite number of samples";
}

TEST(Ex15_2_SamplesForError, InvertsTheLaw) {
  for (double v : {1e-3, 0.03, 2.0})
    for (double r : {0.0, 1e-3, 0.02})
      for (double spp : {1.0, 7.0, 4096.0}) {
        const double e = std::sqrt(v / spp + r * r);
        const auto n = gi::samples_for_error(v, e, r);
        ASSERT_TRUE(n) << "v = " << v << ", r = " << r << ": the error of " << spp << " spp is above r";
        EXPECT_NEAR(*n / spp, 1, 1e-9) << "v = " << v << ", r = " << r << ": e = sqrt(v/N + r^2) at N = " << spp
                                       << " must give N back";
      }
}
