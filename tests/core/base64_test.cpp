#include "gi/core/base64.hpp"

#include <gtest/gtest.h>

#include <string>

TEST(Base64, TheVectorsOfRfc4648) {
  EXPECT_EQ(gi::base64(""), "");
  EXPECT_EQ(gi::base64("f"), "Zg==");
  EXPECT_EQ(gi::base64("fo"), "Zm8=");
  EXPECT_EQ(gi::base64("foo"), "Zm9v");
  EXPECT_EQ(gi::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(gi::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(gi::base64("foobar"), "Zm9vYmFy");
}

TEST(Base64, BytesAboveSevenBitsAndZeros) {
  // 0xFF 0xFE 0x00: 111111 111111 111000 000000; bytes are unsigned whatever char is.
  EXPECT_EQ(gi::base64(std::string("\xFF\xFE\x00", 3)), "//4A");
  EXPECT_EQ(gi::base64(std::string("\x89PNG", 4)), "iVBORw==");
}
