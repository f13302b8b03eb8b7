#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "gi/image/image_io.hpp"

namespace {
std::filesystem::path temp(const std::string& name) { return std::filesystem::path(testing::TempDir()) / "gi_image_test" / name; }

gi::Image ramp() {
  gi::Image image(17, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 17; ++x) image.at(x, y) = gi::Pixel(x / 16.0f, y / 4.0f, 0.25f);
  return image;
}
}  // namespace

TEST(ImageIo, PngRoundTripKeepsEveryCode) {
  const gi::Image image = ramp();
  gi::write_png(image, temp("ramp.png"));
  const gi::Image back = gi::read_png(temp("ramp.png"));
  ASSERT_TRUE(back.same_size(image));
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(gi::to_srgb8(back.pixels[i][c]), gi::to_srgb8(image.pixels[i][c]));
  EXPECT_EQ(gi::to_srgb8(back.at(0, 0).x), 0);  // row 0 is the top
  EXPECT_EQ(gi::to_srgb8(back.at(16, 4).y), 255);
}

TEST(ImageIo, ExposureAndReinhard) {
  gi::Image image(2, 1, gi::Pixel(1.0f));
  gi::write_png(image, temp("tone.png"), 0.5, gi::ToneMap::Clamp);
  EXPECT_EQ(gi::to_srgb8(gi::read_png(temp("tone.png")).at(0, 0).x), gi::to_srgb8(0.5f));
  gi::write_png(image, temp("tone.png"), 1.0, gi::ToneMap::Reinhard);  // 1 / (1 + 1)
  EXPECT_EQ(gi::to_srgb8(gi::read_png(temp("tone.png")).at(0, 0).x), gi::to_srgb8(0.5f));
}

TEST(ImageIo, HdrRoundTripWithinRgbePrecision) {
  // RGBE shares one exponent per pixel: precision is relative to the largest channel.
  gi::Image image(3, 2, gi::Pixel(0.6f, 2.5f, 1.25f));
  gi::write_hdr(image, temp("a.hdr"));
  const gi::Image back = gi::read_hdr(temp("a.hdr"));
  for (const gi::Pixel& p : back.pixels) {
    EXPECT_NEAR(p.x, 0.6f, 2.5f * 0.01f);
    EXPECT_NEAR(p.y, 2.5f, 2.5f * 0.01f);
    EXPECT_NEAR(p.z, 1.25f, 2.5f * 0.01f);
  }
}

TEST(ImageIo, NanImagesAreRefusedNotWritten) {
  gi::Image image(2, 2);
  image.at(1, 1).y = NAN;
  EXPECT_THROW(gi::write_png(image, temp("nan.png")), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(temp("nan.png")));
  EXPECT_THROW(gi::read_png(temp("does_not_exist.png")), std::runtime_error);
}

TEST(ImageIo, EncodedPngIsTheFilesBytes) {
  // The bytes an SVG embeds are those write_png puts in the file, exposure included.
  const gi::Image image = ramp();
  const auto file = temp("encoded.png");
  gi::write_png(image, file, 2.0);
  std::ifstream in(file, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(gi::encode_png(image, 2.0), written);
  EXPECT_NE(gi::encode_png(image, 1.0), written);
  gi::Image bad = image;
  bad.at(3, 2).x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(gi::encode_png(bad), std::runtime_error);
}

TEST(ImageIo, PfmRoundTripIsExact) {
  const gi::Image image = ramp();
  gi::write_pfm(image, temp("ramp.pfm"));
  const gi::Image back = gi::read_pfm(temp("ramp.pfm"));
  ASSERT_TRUE(back.same_size(image));
  EXPECT_EQ(back.pixels, image.pixels);
  gi::write_png(image, temp("not_a.pfm"));
  EXPECT_THROW(gi::read_pfm(temp("not_a.pfm")), std::runtime_error);
}
