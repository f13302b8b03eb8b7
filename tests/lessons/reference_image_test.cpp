// Whitted's scene against a stored reference image, compared as the PNG shows it:
// 8-bit sRGB codes after clamping. Tolerance: RMSE below 0.5 code over all channels
// (a compiler that rounds a few pixels differently flips a code here and there; a
// wrong sign or a missing term changes thousands of pixels by tens of codes).
// On failure the difference image is written beside the test.
// GI_UPDATE_REFERENCES=1 rewrites the reference (after a deliberate change).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/scene/builtin_scenes.hpp"

TEST(ReferenceImage, WhittedSceneMatches) {
  const std::filesystem::path reference_file = std::string(GI_SOURCE_DIR) + "/tests/data/whitted_96x72.png";
  gi::RenderSettings settings;
  settings.width = 96;
  settings.height = 72;
  settings.trace.max_depth = 8;
  const gi::Image image = gi::render(gi::make_world(gi::make_scene("whitted")), settings, 1, 0).image;
  if (std::getenv("GI_UPDATE_REFERENCES")) gi::write_png(image, reference_file);

  const gi::Image reference = gi::read_png(reference_file);
  ASSERT_TRUE(reference.same_size(image));
  double sum = 0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(gi::to_srgb8(image.pixels[i][c])) - gi::to_srgb8(reference.pixels[i][c]);
      sum += d * d;
    }
  const double error = std::sqrt(sum / (3.0 * image.pixels.size()));
  if (error >= 0.5) {
    const std::string diff = std::string(GI_WORK_DIR) + "/whitted_diff.png";
    gi::write_png(gi::difference_image(image, reference), diff);
    gi::write_png(image, std::string(GI_WORK_DIR) + "/whitted_rendered.png");
    FAIL() << "RMSE " << error << " codes against " << reference_file << "; see " << diff;
  }
}
