// Graded tests of exercise 11.3: choosing the shooter. One point per test.
#include <gtest/gtest.h>

#include "gi/radiosity/system/progressive.hpp"
#include "support/print.hpp"

using gi::Color;

namespace {
// A patch of `count` elements from `first`, of the given total area.
gi::Patch patch(int first, int count, double area) { return gi::Patch{gi::Polygon{{}, {}, {}, area}, 0, first, count}; }
}  // namespace

TEST(Ex11_3_Shooter, MostUnshotPowerNotRadiosity) {
  // Patch 0: area 1, unshot 1 (power 1). Patch 1: area 4, unshot 0.5 (power 2).
  const std::vector<gi::Patch> patches = {patch(0, 1, 1.0), patch(1, 1, 4.0)};
  EXPECT_EQ(gi::choose_shooter(patches, {1.0, 4.0}, {Color(1.0), Color(0.5)}), 1)
      << "patch 1 is dimmer (0.5 against 1) but four times larger: it holds twice the unshot power dB_p A_p. "
         "Shoot by power, not by radiosity";
}

TEST(Ex11_3_Shooter, APatchsPowerIsTheSumOverItsElements) {
  // Patch 0: elements 0..2 of areas 1, 1, 2 with unshot 1, 1, 0.25: power 2.5.
  // Patch 1: element 3 of area 1 with unshot 2: power 2.
  const std::vector<gi::Patch> patches = {patch(0, 3, 4.0), patch(3, 1, 1.0)};
  const std::vector<double> area = {1, 1, 2, 1};
  EXPECT_EQ(gi::choose_shooter(patches, area, {Color(1.0), Color(1.0), Color(0.25), Color(2.0)}), 0)
      << "patch 0's power is sum_e dB_e A_e = 1 + 1 + 0.5 = 2.5, more than patch 1's 2: add up every element "
         "of the patch, each times its own area";
}

TEST(Ex11_3_Shooter, ChannelsAreAddedUp) {
  const std::vector<gi::Patch> patches = {patch(0, 1, 1.0), patch(1, 1, 1.0)};
  EXPECT_EQ(gi::choose_shooter(patches, {1.0, 1.0}, {Color(1.0, 0.0, 0.0), Color(0.4, 0.4, 0.4)}), 1)
      << "patch 1's power summed over the channels is 1.2, patch 0's 1.0: compare the sum of the three channels";
}

TEST(Ex11_3_Shooter, TheLargestWherever) {
  const std::vector<gi::Patch> patches = {patch(0, 1, 1.0), patch(1, 1, 1.0), patch(2, 1, 1.0), patch(3, 1, 1.0)};
  const std::vector<double> area = {1, 1, 1, 1};
  EXPECT_EQ(gi::choose_shooter(patches, area, {Color(0.1), Color(3.0), Color(0.2), Color(1.0)}), 1)
      << "the largest of 0.3, 9, 0.6 and 3 summed over channels is patch 1's: keep the largest power seen so far "
         "and compare each patch with it";
  EXPECT_EQ(gi::choose_shooter(patches, area, {Color(3.0), Color(0.1), Color(0.2), Color(1.0)}), 0)
      << "here patch 0 holds the most unshot power";
}

TEST(Ex11_3_Shooter, TheFirstOnATie) {
  const std::vector<gi::Patch> patches = {patch(0, 1, 1.0), patch(1, 1, 1.0), patch(2, 1, 1.0)};
  EXPECT_EQ(gi::choose_shooter(patches, {1.0, 1.0, 1.0}, {Color(0.2), Color(0.5), Color(0.5)}), 1)
      << "patches 1 and 2 hold the same unshot power: take the first (replace the best only when strictly larger)";
}

