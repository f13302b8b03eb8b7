#include "gi/core/onb.hpp"

#include <gtest/gtest.h>

TEST(Onb, IsOrthonormalAndRightHandedForManyNormals) {
  const gi::vec3 normals[] = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},           {0, 1, 0},
                              {0, -1, 0}, {1, 1, 1},  {-0.3, 0.2, -1e-12}, {1e-9, 0, -1}};
  for (gi::vec3 n : normals) {
    n = gi::normalize(n);
    const gi::Onb b(n);
    EXPECT_NEAR(gi::length(b.u), 1.0, 1e-12);
    EXPECT_NEAR(gi::length(b.v), 1.0, 1e-12);
    EXPECT_NEAR(gi::dot(b.u, b.v), 0.0, 1e-12);
    EXPECT_NEAR(gi::dot(b.u, b.w), 0.0, 1e-12);
    EXPECT_NEAR(gi::dot(b.v, b.w), 0.0, 1e-12);
    EXPECT_NEAR(gi::length(gi::cross(b.u, b.v) - b.w), 0.0, 1e-12) << "not right-handed";
  }
}

TEST(Onb, LocalZMapsToNormalAndBack) {
  const gi::vec3 n = gi::normalize(gi::vec3(0.2, -0.5, 0.7));
  const gi::Onb b(n);
  EXPECT_NEAR(gi::length(b.to_world({0, 0, 1}) - n), 0.0, 1e-12);
  const gi::vec3 d(0.3, -0.1, 0.9);
  EXPECT_NEAR(gi::length(b.to_local(b.to_world(d)) - d), 0.0, 1e-12);
}
