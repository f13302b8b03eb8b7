// Graded tests of exercise 14.3: the Russian roulette weight. One point per test.
#include "gi/pathtrace/roulette.hpp"

#include <gtest/gtest.h>

#include "support/print.hpp"

using gi::Color;

TEST(Ex14_3_Roulette, BrightPathsAlwaysGoOn) {
  for (double u : {0.0, 0.5, 0.999999}) {
    Color beta(1.2, 0.5, 0.3);
    EXPECT_TRUE(gi::russian_roulette(beta, u)) << "q = min(1, max component) = 1: the path always goes on";
    EXPECT_EQ(beta, Color(1.2, 0.5, 0.3)) << "with q = 1, beta / q is beta";
  }
}

TEST(Ex14_3_Roulette, GoesOnWithProbabilityTheLargestComponent) {
  Color a(0.3, 0.1, 0.05), b = a;
  EXPECT_TRUE(gi::russian_roulette(a, 0.29)) << "q = 0.3 (the largest component): u = 0.29 < q goes on";
  EXPECT_FALSE(gi::russian_roulette(b, 0.31)) << "q = 0.3: u = 0.31 >= q ends the path";
  Color c(0.05, 0.1, 0.3);
  EXPECT_TRUE(gi::russian_roulette(c, 0.25)) << "q is the largest component, whichever channel it is in";
}

TEST(Ex14_3_Roulette, SurvivorsCarryBetaOverQ) {
  Color beta(0.3, 0.1, 0.05);
  ASSERT_TRUE(gi::russian_roulette(beta, 0.1)) << "u = 0.1 < q = 0.3: the path goes on";
  EXPECT_NEAR(beta.x, 1.0, 1e-12) << "a survivor stands for the paths that were ended: divide by q = 0.3";
  EXPECT_NEAR(beta.y, 0.1 / 0.3, 1e-12) << "every channel is divided by the same q = 0.3";
  EXPECT_NEAR(beta.z, 0.05 / 0.3, 1e-12) << "every channel is divided by the same q = 0.3";
}

TEST(Ex14_3_Roulette, UnbiasedOnAverage) {
  // Over u evenly spread in [0, 1), the mean of what the path carries on (beta' when it
  // goes on, 0 when it ends) must be beta itself: q * (beta / q) + (1 - q) * 0.
  const Color start(0.4, 0.2, 0.1);
  const int n = 100000;
  Color mean(0.0);
  for (int k = 0; k < n; ++k) {
    Color beta = start;
    if (gi::russian_roulette(beta, (k + 0.5) / n)) mean += beta / double(n);
  }
  EXPECT_NEAR(mean.x, 0.4, 1e-4) << "the roulette biases the picture: survivors must carry beta / q, with q the "
                                    "probability of going on (the picture would be "
                                 << mean.x / 0.4 << " times as bright)";
  EXPECT_NEAR(mean.z, 0.1, 1e-4) << "the roulette biases the blue channel: every channel is divided by the one q";
}

TEST(Ex14_3_Roulette, APathThatCarriesNothingEnds) {
  Color beta(0.0);
  EXPECT_FALSE(gi::russian_roulette(beta, 0.0)) << "q = 0: nothing to carry, the path ends whatever u is";
}
