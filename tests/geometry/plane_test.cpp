#include "gi/geometry/plane.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using gi::Plane;
using gi::Ray;
using gi::vec3;

namespace {
const Plane floor_plane{{0, 0, 0}, {0, 1, 0}, 0};
}

TEST(Plane, ObliqueHit) {
  const auto hit = gi::intersect(Ray{{0, 2, 0}, gi::normalize(vec3(1, -1, 0))}, floor_plane);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(hit->point.x, 2.0, 1e-12);
  EXPECT_NEAR(hit->point.y, 0.0, 1e-12);
  EXPECT_EQ(hit->normal, vec3(0, 1, 0));
}

TEST(Plane, HitFromBelowKeepsThePlaneNormal) {
  const auto hit = gi::intersect(Ray{{0, -1, 0}, {0, 1, 0}}, floor_plane);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.0);
  EXPECT_EQ(hit->normal, vec3(0, 1, 0));
}

TEST(Plane, ParallelRayMissesWithoutInfOrNan) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 1, 0}, {1, 0, 0}}, floor_plane));
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 0}, {1, 0, 0}}, floor_plane));  // lying in the plane
}

TEST(Plane, PlaneBehindTheRayIsMissed) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 1, 0}, {0, 1, 0}}, floor_plane));
}

TEST(Plane, GrazingRayStillHitsFarAway) {
  const auto hit = gi::intersect(Ray{{0, 1, 0}, gi::normalize(vec3(1, -1e-6, 0))}, floor_plane);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x, 1e6, 1e-3);
}

TEST(Plane, BadPlanesAreRejected) {
  EXPECT_THROW(gi::check(Plane{{0, 0, 0}, {0, 2, 0}, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Plane{{0, 0, 0}, {0, 0, 0}, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Plane{{NAN, 0, 0}, {0, 1, 0}, 0}), std::invalid_argument);
}
