#include "gi/scene/camera.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using gi::Camera;
using gi::vec3;

TEST(Camera, CentreRayLooksAtTheTarget) {
  const Camera camera{{1, 2, 3}, {1, 2, -7}, {0, 1, 0}, 60};
  const auto frame = gi::camera_frame(camera, 200, 100);
  const gi::Ray ray = gi::primary_ray(frame, 100, 50);  // the image centre
  EXPECT_EQ(ray.origin, vec3(1, 2, 3));
  EXPECT_NEAR(gi::length(ray.direction - vec3(0, 0, -1)), 0.0, 1e-12);
}

TEST(Camera, TopAndBottomEdgesSpanTheVerticalFieldOfView) {
  const Camera camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60};
  const auto frame = gi::camera_frame(camera, 300, 200);
  const vec3 top = gi::primary_ray(frame, 150, 0).direction;
  const vec3 bottom = gi::primary_ray(frame, 150, 200).direction;
  EXPECT_NEAR(std::acos(gi::dot(top, bottom)) * 180 / gi::pi, 60.0, 1e-9);
  EXPECT_GT(top.y, 0) << "row 0 must be the top of the image";
  // Square pixels: the horizontal field is wider by the aspect ratio (in tangent).
  const vec3 right = gi::primary_ray(frame, 300, 100).direction;
  EXPECT_NEAR(right.x / -right.z, 1.5 * std::tan(gi::pi / 6), 1e-12);
  EXPECT_GT(right.x, 0) << "x must grow to the right";
}

TEST(Camera, DegenerateCamerasAreRejected) {
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 45}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 180}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{}, 0, 10), std::invalid_argument);
}
