#include "gi/render/scene_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>

TEST(SceneLines, ASegmentLandsWhereTheCameraSeesItsPoints) {
  // The default camera looks down -z from the origin (45 degrees top to bottom): a
  // segment 2 in front of it, half a pixel below the axis, from far left to far right,
  // runs along the middle of row 15, and nothing else is drawn.
  const gi::Camera camera;
  const gi::CameraFrame frame = gi::camera_frame(camera, 40, 30);
  const double pixel = 2 * 2 * std::tan(gi::pi / 8) / 30;  // a pixel's height, 2 in front of the eye
  gi::Image picture(40, 30);
  gi::draw_segment(picture, frame, {-3, -pixel / 2, -2}, {3, -pixel / 2, -2}, gi::Pixel(1));
  int lit = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      if (picture.at(x, y) == gi::Pixel(1)) {
        ++lit;
        EXPECT_EQ(y, 15) << "on the middle row only";
      }
  EXPECT_EQ(lit, 40) << "the segment runs past both edges: every pixel of the row, once";
  // Behind the eye: nothing.
  gi::Image behind(40, 30);
  gi::draw_segment(behind, frame, {-1, 0, 2}, {1, 0, 2}, gi::Pixel(1));
  for (const gi::Pixel& p : behind.pixels) EXPECT_EQ(p, gi::Pixel(0));
}
