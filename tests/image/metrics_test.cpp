#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gi/image/metrics.hpp"

namespace {
gi::Image grey(float v) { return gi::Image(2, 2, gi::Pixel(v)); }
}  // namespace

TEST(Metrics, OneChannelOfOnePixelOff) {
  gi::Image a = grey(0.5f), b = grey(0.5f);
  b.at(1, 0).y = 0.6f;
  // One of 12 channel values differs by 0.1: MSE = 0.01 / 12.
  EXPECT_NEAR(gi::mse(a, b), 0.01 / 12, 1e-9);
  EXPECT_NEAR(gi::rmse(a, b), std::sqrt(0.01 / 12), 1e-8);
  EXPECT_NEAR(gi::psnr(a, b), 10 * std::log10(12 / 0.01), 1e-5);
}

TEST(Metrics, IdenticalImages) {
  EXPECT_EQ(gi::rmse(grey(0.3f), grey(0.3f)), 0.0);
  EXPECT_TRUE(std::isinf(gi::psnr(grey(0.3f), grey(0.3f))));
}

TEST(Metrics, RelativeMseWeighsDarkErrorsMore) {
  // The same absolute error of 0.1 on a dark and on a bright reference.
  const double dark = gi::relative_mse(grey(0.2f), grey(0.1f));
  const double bright = gi::relative_mse(grey(1.0f), grey(0.9f));
  EXPECT_NEAR(dark, 0.01 / (0.01 + 0.01), 1e-6);
  EXPECT_NEAR(bright, 0.01 / (0.81 + 0.01), 1e-6);
}

TEST(Metrics, SizeMismatchThrows) {
  EXPECT_THROW(gi::rmse(gi::Image(2, 2), gi::Image(2, 3)), std::invalid_argument);
  EXPECT_THROW(gi::Image(0, 3), std::invalid_argument);
  EXPECT_THROW(gi::Image(-4, 3), std::invalid_argument);
}
