// Scoring a picture against a reference away from edges (picture_error.hpp): which
// blocks count, and the two measures on pictures with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace {

TEST(InteriorBlocks, LeaveOutEdgesAndTheLight) {
  const gi::RadiosityScene box = gi::cornell_box();
  const gi::BlockMask mask = gi::interior_blocks(box.surfaces, box.camera, 256, 256, 8);
  ASSERT_EQ(mask.blocks_x, 32);
  ASSERT_EQ(mask.blocks_y, 32);
  // The picture's border blocks touch the edge of the frame: never interior.
  for (int i = 0; i < 32; ++i) {
    EXPECT_FALSE(mask.interior[i]) << "top row";
    EXPECT_FALSE(mask.interior[31 * 32 + i]) << "bottom row";
  }
  // No block with a pixel that sees the light counts.
  const gi::Mesh whole = gi::make_mesh(box.surfaces, {});
  const gi::FormFactorScene scene(gi::element_shapes(whole));
  const gi::CameraFrame frame = gi::camera_frame(box.camera, 256, 256);
  int light_pixels = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const auto hit = scene.first_hit(gi::primary_ray(frame, x + 0.5, y + 0.5));
      if (!hit || box.surfaces[whole.elements[hit->polygon].surface].name != "light") continue;
      ++light_pixels;
      EXPECT_FALSE(mask.interior[(y / 8) * 32 + x / 8]) << "pixel " << x << ", " << y << " sees the light";
    }
  EXPECT_GT(light_pixels, 50);
  // The back wall's middle is one surface, far from every edge.
  EXPECT_TRUE(mask.interior[9 * 32 + 15]);
  // About 60% of the picture lies inside one surface each.
  EXPECT_GT(mask.count(), 500);
  EXPECT_LT(mask.count(), 800);
  EXPECT_THROW(gi::interior_blocks(box.surfaces, box.camera, 256, 256, 7), std::invalid_argument);
}

// A 4 x 2 picture of 2 x 2 blocks, both kept: reference (1, 2, 4) and (2, 2, 2) in the
// two blocks, the test 10% too bright in the first block only.
TEST(PictureError, KnownAnswers) {
  gi::BlockMask mask{2, 2, 1, {1, 1}};
  gi::Image reference(4, 2), test(4, 2), se(4, 2, gi::Pixel(0.2f));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      reference.at(x, y) = x < 2 ? gi::Pixel(1, 2, 4) : gi::Pixel(2, 2, 2);
      test.at(x, y) = x < 2 ? gi::Pixel(1.1f, 2.2f, 4.4f) : gi::Pixel(2, 2, 2);
    }
  const gi::PictureError e = gi::picture_error(test, reference, mask);
  // sum of squared differences 0.01 + 0.04 + 0.16 over sum of squares 1 + 4 + 16 + 12.
  EXPECT_NEAR(e.relative_rms, std::sqrt(0.21 / 33), 1e-6);
  // Three channels 10% off and three exact: sqrt(3 * 0.01 / 6).
  EXPECT_NEAR(e.block_relative, std::sqrt(0.005), 1e-6);
  // A block's standard error: sqrt(4 * 0.04) / 4 = 0.1 in every channel.
  const gi::PictureError noise = gi::reference_noise(se, reference, mask);
  EXPECT_NEAR(noise.relative_rms, std::sqrt(6 * 0.01 / 33), 1e-6);
  EXPECT_NEAR(noise.block_relative, std::sqrt((0.01 + 0.0025 + 0.000625 + 3 * 0.0025) / 6), 1e-6);
  // Leaving the second block out leaves only the first's error.
  mask.interior = {1, 0};
  EXPECT_NEAR(gi::picture_error(test, reference, mask).block_relative, 0.1, 1e-6);
  mask.interior = {0, 0};
  EXPECT_THROW(gi::picture_error(test, reference, mask), std::invalid_argument);
  EXPECT_THROW(gi::picture_error(gi::Image(2, 2), gi::Image(2, 2), {2, 2, 1, {1, 1}}), std::invalid_argument);
}

}  // namespace
