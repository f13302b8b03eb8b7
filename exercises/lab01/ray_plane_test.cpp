// Graded tests of exercise 1.2: ray-plane intersection. One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/geometry/plane.hpp"
#include "support/print.hpp"

using gi::Plane;
using gi::Ray;
using gi::vec3;

namespace {
const Plane tilted{{0, 1, 0}, gi::normalize(vec3(0, 1, 1)), 3};
const Plane floor_plane{{0, 0, 0}, {0, 1, 0}, 2};
}  // namespace

TEST(Ex1_2_RayPlane, ObliqueHit) {
  const auto hit = gi::intersect(Ray{{0, 2, 0}, gi::normalize(vec3(1, -1, 0))}, floor_plane);
  ASSERT_TRUE(hit) << "a ray heading down at 45 degrees from y = 2 meets the floor y = 0";
  EXPECT_NEAR(hit->t, 2 * std::sqrt(2.0), 1e-9) << "t = (p - o).n / (d.n)";
  EXPECT_NEAR(gi::length(hit->point - vec3(2, 0, 0)), 0, 1e-9) << "the hit point is ray.at(t) = o + t d";
  EXPECT_EQ(hit->material, 2) << "pass the plane's material index on in the Hit";
}

TEST(Ex1_2_RayPlane, PlaneNotThroughTheOrigin) {
  const auto hit = gi::intersect(Ray{{0, 5, 0}, {0, -1, 0}}, tilted);
  ASSERT_TRUE(hit) << "a ray down the y axis meets the tilted plane y + z = 1 at y = 1";
  // The plane y + z = 1 meets the vertical line x = z = 0 at y = 1.
  EXPECT_NEAR(hit->t, 4.0, 1e-9) << "use the plane's point p in (p - o).n; this plane does not pass through the origin";
}

TEST(Ex1_2_RayPlane, ParallelRayMisses) {
  const auto hit = gi::intersect(Ray{{0, 1, 0}, {1, 0, 0}}, floor_plane);
  EXPECT_FALSE(hit) << "d.n = 0: the ray runs parallel to the plane; test for it before dividing";
  EXPECT_FALSE(gi::intersect(Ray{{0, 0, 0}, {0, 0, 1}}, floor_plane))
      << "a ray lying in the plane counts as a miss (0/0 would give NaN)";
}

TEST(Ex1_2_RayPlane, PlaneBehindTheRayIsMissed) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 1, 0}, {0, 1, 0}}, floor_plane))
      << "t = -1 is behind the origin; reject t < t_min";
}

TEST(Ex1_2_RayPlane, HitFromEitherSide) {
  const auto hit = gi::intersect(Ray{{0, -3, 0}, {0, 1, 0}}, floor_plane);
  ASSERT_TRUE(hit) << "a plane is two-sided: a ray from below (d.n > 0) hits it too";
  EXPECT_NEAR(hit->t, 3.0, 1e-9) << "from y = -3 the floor is 3 away";
  EXPECT_EQ(hit->normal, vec3(0, 1, 0)) << "return the plane's own normal; the tracer flips it to face the ray";
}

TEST(Ex1_2_RayPlane, RespectsTMax) {
  EXPECT_FALSE(gi::intersect(Ray{{0, 2, 0}, {0, -1, 0}, 0.0, 1.5}, floor_plane))
      << "the plane is 2 away but t_max = 1.5";
  EXPECT_TRUE(gi::intersect(Ray{{0, 2, 0}, {0, -1, 0}, 0.0, 2.5}, floor_plane))
      << "the plane is 2 away and t_max = 2.5: a hit";
}

TEST(Ex1_2_RayPlane, UnnormalisedDirection) {
  const auto hit = gi::intersect(Ray{{0, 2, 0}, {0, -4, 0}}, floor_plane);
  ASSERT_TRUE(hit) << "a ray straight down from y = 2 hits the floor";
  EXPECT_NEAR(hit->t, 0.5, 1e-9) << "t is in units of the direction: do not normalise d inside the intersection";
  EXPECT_NEAR(gi::length(hit->point - vec3(0, 0, 0)), 0, 1e-9) << "the hit point is o + t d with d as given";
}
