// Graded tests of exercise 1.1: ray-sphere intersection. One point per test.
#include <gtest/gtest.h>

#include "gi/geometry/sphere.hpp"
#include "support/print.hpp"

using gi::Ray;
using gi::Sphere;
using gi::vec3;

namespace {
const Sphere ball{{0, 0, -5}, 1, 7};  // material 7, to check it is passed on
}

TEST(Ex1_1_RaySphere, ReturnsTheNearerRootFromOutside) {
  const auto hit = gi::intersect(Ray{{0, 0, 0}, {0, 0, -1}}, ball);
  ASSERT_TRUE(hit) << "a ray straight at the sphere's centre must hit it";
  EXPECT_NEAR(hit->t, 4.0, 1e-9) << (std::abs(hit->t - 6.0) < 1e-6
                                          ? "t = 6 is the far side of the sphere: return the smaller root (-h - sqrt)/a first"
                                          : "the front of the sphere is 4 units away");
}

TEST(Ex1_1_RaySphere, OffCentreHit) {
  const auto hit = gi::intersect(Ray{{0.6, 0, 0}, {0, 0, -1}}, ball);
  ASSERT_TRUE(hit) << "a ray 0.6 off the axis of a unit sphere hits it";
  EXPECT_NEAR(hit->t, 5.0 - 0.8, 1e-9) << "a ray 0.6 off the axis of a unit sphere enters at depth sqrt(1 - 0.36) = 0.8";
}

TEST(Ex1_1_RaySphere, StartingInsideReturnsTheFarRoot) {
  const auto hit = gi::intersect(Ray{{0, 0, -5.5}, {0, 0, -1}}, ball);
  ASSERT_TRUE(hit) << "a ray that starts inside the sphere always hits it (this is how refracted rays leave glass)";
  EXPECT_NEAR(hit->t, 0.5, 1e-9) << (hit->t < 0 ? "a negative t is behind the ray's origin: when the near root is "
                                                   "below t_min, try the far root"
                                                 : "wrong distance to the far side");
}

TEST(Ex1_1_RaySphere, SphereBehindTheRayIsMissed) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 0}, {0, 0, 1}}, ball))
      << "both roots are negative: the sphere is behind the ray's origin, which is a miss";
}

TEST(Ex1_1_RaySphere, MissWhenTheDiscriminantIsNegative) {
  EXPECT_FALSE(gi::intersect(Ray{{1.01, 0, 0}, {0, 0, -1}}, ball)) << "this ray passes 1.01 from the centre";
  EXPECT_FALSE(gi::intersect(Ray{{0, 3, 0}, gi::normalize(vec3(0, 0.1, -1))}, ball))
      << "this ray rises away above the sphere: h^2 - a c0 < 0, a miss";
}

TEST(Ex1_1_RaySphere, TangentRayTouches) {
  const auto hit = gi::intersect(Ray{{1, 0, 0}, {0, 0, -1}}, ball);
  ASSERT_TRUE(hit) << "a discriminant of exactly 0 is a (tangent) hit: test discriminant < 0 for a miss, not <= 0";
  EXPECT_NEAR(hit->t, 5.0, 1e-6) << "the tangent point is 5 along the ray";
}

TEST(Ex1_1_RaySphere, RespectsTMinAndTMax) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 0}, {0, 0, -1}, 0.0, 3.0}, ball))
      << "the sphere is beyond t_max = 3: a shadow ray to a light 3 units away must not see it";
  const auto far = gi::intersect(Ray{{0, 0, 0}, {0, 0, -1}, 4.5}, ball);
  ASSERT_TRUE(far) << "with t_min = 4.5 the near root (4) is excluded but the far root (6) is not";
  EXPECT_NEAR(far->t, 6.0, 1e-9) << "the far side of the sphere is 6 along the ray";
}

TEST(Ex1_1_RaySphere, UnnormalisedDirection) {
  const auto hit = gi::intersect(Ray{{0, 0, 0}, {0, 0, -2}}, ball);
  ASSERT_TRUE(hit) << "a ray with direction (0, 0, -2) at the sphere's centre must hit it";
  EXPECT_NEAR(hit->t, 2.0, 1e-9) << "t is measured in units of the direction: with |d| = 2 the hit is at t = 2. "
                                    "Keep a = d.d in the quadratic instead of assuming a = 1";
  EXPECT_NEAR(gi::length(hit->point - vec3(0, 0, -4)), 0, 1e-9)
      << "the hit point is ray.at(t) = origin + t * direction with the direction as given (here (0, 0, -2)), "
         "not a normalised one";
}

TEST(Ex1_1_RaySphere, HitPointNormalAndMaterial) {
  const Sphere big{{1, 2, 3}, 2, 4};
  const auto hit = gi::intersect(Ray{{1, 2, 10}, {0, 0, -1}}, big);
  ASSERT_TRUE(hit) << "a ray straight at the centre of the sphere at (1, 2, 3) must hit it";
  EXPECT_NEAR(gi::length(hit->point - vec3(1, 2, 5)), 0, 1e-9) << "the hit point is origin + t * direction";
  EXPECT_NEAR(gi::length(hit->normal), 1.0, 1e-9) << "the normal must be unit length: divide (p - c) by the radius";
  EXPECT_NEAR(hit->normal.z, 1.0, 1e-9) << "the normal points outwards, (p - c) / r";
  EXPECT_EQ(hit->material, 4) << "pass the sphere's material index on in the Hit";
}
