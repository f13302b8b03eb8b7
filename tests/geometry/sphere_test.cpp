#include "gi/geometry/sphere.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using gi::Ray;
using gi::Sphere;
using gi::vec3;

namespace {
const Sphere unit{{0, 0, 0}, 1.0, 0};
}

TEST(Sphere, HeadOnHitReturnsNearSideWithOutwardNormal) {
  const auto hit = gi::intersect(Ray{{0, 0, 5}, {0, 0, -1}}, unit);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 4.0);
  EXPECT_EQ(hit->point, vec3(0, 0, 1));
  EXPECT_EQ(hit->normal, vec3(0, 0, 1));
}

TEST(Sphere, UnnormalisedDirectionMeasuresTInDirectionUnits) {
  const auto hit = gi::intersect(Ray{{0, 0, 5}, {0, 0, -2}}, unit);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 2.0);
}

TEST(Sphere, MissAndSphereBehindTheRay) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 2, 5}, {0, 0, -1}}, unit));
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 5}, {0, 0, 1}}, unit));
}

TEST(Sphere, OriginInsideHitsFarSide) {
  const auto hit = gi::intersect(Ray{{0, 0, 0.5}, {0, 0, -1}}, unit);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.5);
  EXPECT_EQ(hit->normal, vec3(0, 0, -1));  // outward, pointing along the ray
}

TEST(Sphere, TangentRayTouchesOnce) {
  const auto hit = gi::intersect(Ray{{1, 0, 5}, {0, 0, -1}}, unit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 5.0, 1e-6);
  EXPECT_NEAR(hit->normal.x, 1.0, 1e-6);
}

TEST(Sphere, RespectsTMinAndTMax) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 5}, {0, 0, -1}, 0, 3.9}, unit));
  const auto far = gi::intersect(Ray{{0, 0, 5}, {0, 0, -1}, 4.5}, unit);
  ASSERT_TRUE(far);
  EXPECT_DOUBLE_EQ(far->t, 6.0);
}

TEST(Sphere, SmallSphereFarAwayKeepsItsDigits) {
  // b^2 - 4ac loses every digit here (b^2 ~ 1e16, 4ac differs by ~1e-2).
  const Sphere tiny{{0, 0, -1e8}, 0.05, 0};
  const auto hit = gi::intersect(Ray{{0.03, 0, 0}, {0, 0, -1}}, tiny);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1e8 - 0.04, 1e-6);
}

TEST(Sphere, DegenerateSpheresAreRejected) {
  EXPECT_THROW(gi::check(Sphere{{0, 0, 0}, 0.0, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Sphere{{0, 0, 0}, -1.0, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Sphere{{0, 0, 0}, std::nan(""), 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Sphere{{0, INFINITY, 0}, 1.0, 0}), std::invalid_argument);
  EXPECT_NO_THROW(gi::check(unit));
}
