// Graded tests of exercise 3.2: Whitted's adaptive subdivision decision. One point
// per test. The corners of a square "differ" when any corner's radiance is more than
// the threshold away from the mean of the four, in any colour channel.
#include <gtest/gtest.h>

#include "gi/render/adaptive.hpp"
#include "gi/render/pixel_samplers.hpp"
#include "support/print.hpp"

using gi::Color;

TEST(Ex3_2_Adaptive, EqualCornersAreNotSplit) {
  EXPECT_FALSE(gi::should_subdivide({Color(0.3), Color(0.3), Color(0.3), Color(0.3)}, 0.1))
      << "four equal corners need no more samples";
}

TEST(Ex3_2_Adaptive, BrightCornersAreNotSplitJustForBeingBright) {
  EXPECT_FALSE(gi::should_subdivide({Color(3.0), Color(3.0), Color(3.0), Color(3.0)}, 0.1))
      << "compare the corners with each other (their mean), not with zero";
}

TEST(Ex3_2_Adaptive, AnEdgeIsSplit) {
  EXPECT_TRUE(gi::should_subdivide({Color(0.0), Color(1.0), Color(0.0), Color(1.0)}, 0.1))
      << "corners 0 and 1 straddle an edge: subdivide";
}

TEST(Ex3_2_Adaptive, SmallDifferencesAreNotSplit) {
  EXPECT_FALSE(gi::should_subdivide({Color(0.50), Color(0.55), Color(0.50), Color(0.55)}, 0.1))
      << "the corners are within 0.025 of their mean, below the threshold 0.1";
}

TEST(Ex3_2_Adaptive, ADarkerCornerCountsToo) {
  // Mean 0.875: three corners are 0.125 above it, one is 0.375 below.
  // The same corners with the dark one first: only the order changed, so must the answer not.
  const bool dark_first = gi::should_subdivide({Color(0.5), Color(1.0), Color(1.0), Color(1.0)}, 0.2);
  EXPECT_TRUE(gi::should_subdivide({Color(1.0), Color(1.0), Color(1.0), Color(0.5)}, 0.2))
      << (dark_first ? "the last corner is 0.375 darker than the mean 0.875, more than 0.2: split. You split when "
                       "the dark corner comes first but not when it comes last: check all four corners"
                     : "one corner is 0.375 darker than the mean: take the absolute difference");
}

TEST(Ex3_2_Adaptive, EveryColourChannelCounts) {
  // Blue alone changes: the mean is 0.15 in blue, every corner 0.15 away from it.
  EXPECT_TRUE(gi::should_subdivide({Color(0.2, 0.2, 0.0), Color(0.2, 0.2, 0.3), Color(0.2, 0.2, 0.0),
                                    Color(0.2, 0.2, 0.3)},
                                   0.1))
      << "the corners differ by 0.15 from their mean in blue only (a red-green edge in a blue world): compare "
         "every channel on its own. Averaging the channels (or taking the luminance) first shrinks the "
         "difference below the threshold";
}

TEST(Ex3_2_Adaptive, ChannelsAreNotAddedUp) {
  // Every channel 0.06 from its mean: below 0.1 in each, though 0.18 summed.
  // The same corners in red only: no sum over channels can reach 0.1 there.
  const bool red_only = gi::should_subdivide({Color(0.0, 0.0, 0.0), Color(0.12, 0.0, 0.0), Color(0.0, 0.0, 0.0),
                                              Color(0.12, 0.0, 0.0)},
                                             0.1);
  EXPECT_FALSE(gi::should_subdivide({Color(0.0), Color(0.12), Color(0.0), Color(0.12)}, 0.1))
      << (red_only ? "the mean of the four corners is 0.06 and each is 0.06 from it, below the threshold 0.1: no split. "
                     "You split even when only red changes, so you measure 0.12, the difference between two corners: "
                     "compare each corner with the mean of the four, not with the first corner, nor take the "
                     "brightest minus the darkest"
                   : "each channel is 0.06 from its mean, below the threshold 0.1: no split. Take the largest "
                     "channel's difference, not the sum over channels");
}

TEST(Ex3_2_Adaptive, TheThresholdIsStrict) {
  // Mean 0.5, every corner exactly 0.5 away: representable, so no round-off.
  EXPECT_FALSE(gi::should_subdivide({Color(0.0), Color(1.0), Color(0.0), Color(1.0)}, 0.5))
      << "subdivide when the difference is MORE than the threshold, not equal to it";
  EXPECT_TRUE(gi::should_subdivide({Color(0.0), Color(1.0), Color(0.0), Color(1.0)}, 0.49))
      << "every corner is 0.5 from the mean, more than 0.49: split";
}

TEST(Ex3_2_Adaptive, CompareWithTheMeanNotTheFirstCorner) {
  // Mean 0.1125: corner 0 is 0.1125 below it, the others 0.0375 above: no split at 0.12,
  // though corners 0 and 1 differ by 0.15.
  EXPECT_FALSE(gi::should_subdivide({Color(0.0), Color(0.15), Color(0.15), Color(0.15)}, 0.12))
      << "measure each corner against the mean of the four, as the handout defines it";
}

TEST(Ex3_2_Adaptive, DrivesTheAdaptiveSamplerOnAnEdge) {
  // A vertical edge at x = 0.3 through the pixel. Two levels: the pixel splits (5 new
  // samples), its two left quarters straddle the edge and split again (5 each).
  const auto edge = [](gi::vec2 p) { return Color(p.x >= 0.3 ? 1.0 : 0.0); };
  const gi::AdaptiveSample a = gi::adaptive_sample(edge, 0.1, 2);
  EXPECT_EQ(a.samples, 19) << "4 corners + 5 (pixel) + 5 + 5 (the two quarters the edge crosses)";
  EXPECT_NEAR(a.colour.x, 0.625, 1e-12) << "the estimate of a pixel 70% white, from 19 samples, is 0.625";
}
