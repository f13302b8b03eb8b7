#include <gtest/gtest.h>

#include <cmath>

#include "gi/image/image_io.hpp"

TEST(Srgb, KnownCodes) {
  EXPECT_EQ(gi::to_srgb8(0.0f), 0);
  EXPECT_EQ(gi::to_srgb8(1.0f), 255);
  EXPECT_EQ(gi::to_srgb8(0.5f), 188);       // 255 * (1.055 * 0.5^(1/2.4) - 0.055) = 187.5 + ...
  EXPECT_EQ(gi::to_srgb8(0.0031308f), 10);  // the knee of the curve: 255 * 0.04045 = 10.3
  EXPECT_EQ(gi::to_srgb8(-1.0f), 0);
  EXPECT_EQ(gi::to_srgb8(7.0f), 255);
  EXPECT_EQ(gi::to_srgb8(NAN), 0);
}

TEST(Srgb, TableAgreesWithTheExactCurveEverywhere) {
  // The fast lookup must round exactly as round(255 * encode(c)) does.
  for (int i = 0; i <= 200000; ++i) {
    const float c = i / 200000.0f;
    const long expected = std::lround(255.0 * gi::srgb_encode(c));
    ASSERT_EQ(gi::to_srgb8(c), expected) << "at linear " << c;
  }
}

TEST(Srgb, EveryCodeRoundTrips) {
  for (int code = 0; code < 256; ++code)
    ASSERT_EQ(gi::to_srgb8(gi::from_srgb8(static_cast<std::uint8_t>(code))), code);
  EXPECT_NEAR(gi::srgb_decode(gi::srgb_encode(0.2)), 0.2, 1e-12);
}
