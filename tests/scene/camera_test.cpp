#include "gi/scene/camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(Camera, ImagePositionInvertsThePrimaryRay) {
  // A point anywhere along the eye ray through (x, y) appears at (x, y); a point behind
  // the eye, or beside it, appears nowhere.
  const Camera camera{{1, 2, 3}, {-4, 0.5, -7}, {0, 1, 0}, 50};
  const auto frame = gi::camera_frame(camera, 320, 240);
  for (const glm::dvec2 xy : {glm::dvec2(0, 0), glm::dvec2(160, 120), glm::dvec2(319.75, 3.5), glm::dvec2(-40, 300)})
    for (double t : {0.01, 1.0, 250.0}) {
      const auto at = gi::image_position(frame, gi::primary_ray(frame, xy.x, xy.y).at(t));
      ASSERT_TRUE(at.has_value());
      EXPECT_NEAR(at->x, xy.x, 1e-9 * std::max(1.0, t));
      EXPECT_NEAR(at->y, xy.y, 1e-9 * std::max(1.0, t));
    }
  const gi::Ray centre = gi::primary_ray(frame, 160, 120);
  EXPECT_FALSE(gi::image_position(frame, centre.at(-1.0)).has_value());
  EXPECT_FALSE(gi::image_position(frame, camera.eye).has_value());
}

TEST(Camera, DegenerateCamerasAreRejected) {
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 45}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 180}, 10, 10), std::invalid_argument);
  EXPECT_THROW(gi::camera_frame(Camera{}, 0, 10), std::invalid_argument);
}
