// The processor's path to a lane mask (SSE2, NEON) against the portable loop
// (simd.hpp): the same bits for every pattern of true and false lanes, for four floats
// and for four doubles, NaNs and signed zeros included.
#include "gi/core/simd.hpp"

#include <gtest/gtest.h>

#include <limits>

using gi::simd::double4;
using gi::simd::float4;

namespace {

// Lane j is 1 where bit j of `pattern` is set, else 0; compared with 0.5, lane j is
// true exactly where the bit is set. (Filled in place: GCC warns of a double4 returned
// by value without AVX.)
template <class Lanes>
void fill(Lanes& lanes, unsigned pattern) {
  for (int j = 0; j < 4; ++j) lanes[j] = pattern >> j & 1 ? 1 : 0;
}

}  // namespace

TEST(LaneMask, EveryPatternOfFourFloats) {
  for (unsigned pattern = 0; pattern < 16; ++pattern) {
    float4 lanes;
    fill(lanes, pattern);
    const auto greater = lanes > gi::simd::splat(0.5f);
    EXPECT_EQ(gi::simd::lane_mask(greater), pattern);
    EXPECT_EQ(gi::simd::lane_mask_portable(greater), pattern);
    const auto not_greater = lanes <= gi::simd::splat(0.5f);
    EXPECT_EQ(gi::simd::lane_mask(not_greater), ~pattern & 0xf);
  }
}

TEST(LaneMask, EveryPatternOfFourDoubles) {
  for (unsigned pattern = 0; pattern < 16; ++pattern) {
    double4 lanes;
    fill(lanes, pattern);
    const double4 half = {0.5, 0.5, 0.5, 0.5};
    const auto greater = lanes > half;
    EXPECT_EQ(gi::simd::lane_mask(greater), pattern);
    EXPECT_EQ(gi::simd::lane_mask_portable(greater), pattern);
    const auto not_greater = lanes <= half;
    EXPECT_EQ(gi::simd::lane_mask(not_greater), ~pattern & 0xf);
  }
}

// A NaN lane compares false either way; -0 equals +0; infinities order as numbers.
TEST(LaneMask, NaNsSignedZerosAndInfinities) {
  const float nanf = std::numeric_limits<float>::quiet_NaN(), inff = std::numeric_limits<float>::infinity();
  const float4 a{nanf, -0.0f, inff, -inff}, b{0.0f, 0.0f, 1.0f, 1.0f};
  EXPECT_EQ(gi::simd::lane_mask(a < b), 0b1000u);
  EXPECT_EQ(gi::simd::lane_mask(a >= b), 0b0110u);
  EXPECT_EQ(gi::simd::lane_mask(a == b), 0b0010u);
  EXPECT_EQ(gi::simd::lane_mask(a < b), gi::simd::lane_mask_portable(a < b));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const double4 c{-inf, nan, -0.0, inf}, d{1.0, 0.0, 0.0, 1.0};
  EXPECT_EQ(gi::simd::lane_mask(c < d), 0b0001u);
  EXPECT_EQ(gi::simd::lane_mask(c >= d), 0b1100u);
  EXPECT_EQ(gi::simd::lane_mask(c != d), 0b1011u) << "a NaN differs from everything";
  EXPECT_EQ(gi::simd::lane_mask(c >= d), gi::simd::lane_mask_portable(c >= d));
}

TEST(Lanes, LoadReadsFourUnalignedFloats) {
  const float f[5] = {1, 2, 3, 4, 5};
  const float4 v = gi::simd::load(f + 1);  // 4 bytes past an alignment a vector would want
  EXPECT_EQ(gi::simd::lane_mask(v == float4{2, 3, 4, 5}), 0xfu);
}
