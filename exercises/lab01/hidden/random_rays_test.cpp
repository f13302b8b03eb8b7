// Hidden graded tests of lab 1 (the autograder's; kits leave hidden/ out): random rays
// against random spheres and planes, checked against geometry, not a second solution.
// One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/core/rng.hpp"
#include "gi/geometry/plane.hpp"
#include "gi/geometry/sphere.hpp"
#include "support/print.hpp"
#include "support/random.hpp"

using gi::Ray;
using gi::vec3;

using support::random_vector;

TEST(Ex1_1_RandomRays, HitOrMissAsTheGeometrySays) {
  // A ray segment [t_min, t_max] meets the sphere iff its point nearest the centre is
  // within the radius; rays within 1e-6 of tangent are left out.
  gi::Rng rng(101);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const gi::Sphere sphere{random_vector(rng, 5), 0.2 + 2 * rng.uniform(), 1};
    // Aimed near the sphere, with a direction of any length, starting anywhere (inside too).
    const vec3 origin = random_vector(rng, 6), aim = sphere.center + random_vector(rng, 1.5 * sphere.radius);
    const Ray ray{origin, (0.3 + 2 * rng.uniform()) * (aim - origin), 0.1 * rng.uniform(), 0.3 + 2 * rng.uniform()};
    if (gi::length(ray.direction) < 0.1) continue;
    const double t_star = std::clamp(gi::dot(sphere.center - ray.origin, ray.direction) /
                                         gi::dot(ray.direction, ray.direction), ray.t_min, ray.t_max);
    const double nearest = gi::length(ray.at(t_star) - sphere.center);
    const double d_min = gi::length(ray.at(ray.t_min) - sphere.center), d_max = gi::length(ray.at(ray.t_max) - sphere.center);
    const bool meets = nearest <= sphere.radius && (d_min >= sphere.radius || d_max >= sphere.radius);
    if (std::abs(nearest - sphere.radius) < 1e-6 || std::abs(d_min - sphere.radius) < 1e-6 ||
        std::abs(d_max - sphere.radius) < 1e-6)
      continue;
    const auto hit = gi::intersect(ray, sphere);
    ASSERT_EQ(hit.has_value(), meets)
        << (meets ? "a miss, but this ray crosses the sphere's surface within [t_min, t_max]"
                  : "a hit, but this ray does not cross the sphere's surface within [t_min, t_max]")
        << " (random ray " << k << ": " << testing::PrintToString(ray) << ", sphere at "
        << testing::PrintToString(sphere.center) << " of radius " << sphere.radius << ")";
    if (!hit) continue;
    ++hits;
    ASSERT_NEAR(gi::length(hit->point - sphere.center), sphere.radius, 1e-9 * (1 + sphere.radius))
        << "the hit point must lie on the sphere (random ray " << k << ")";
    ASSERT_TRUE(hit->t >= ray.t_min && hit->t <= ray.t_max) << "t outside [t_min, t_max] (random ray " << k << ")";
    const bool inside_at_start = d_min < sphere.radius;
    const double radial = gi::dot(hit->point - sphere.center, ray.direction);
    ASSERT_TRUE(inside_at_start ? radial >= 0 : radial <= 0)
        << (inside_at_start ? "starting inside, the first crossing is on the way out"
                            : "starting outside, the first crossing is on the way in: the nearer root")
        << " (random ray " << k << ")";
  }
  EXPECT_GT(hits, 100) << "the random rays should hit often enough to test something";
}

TEST(Ex1_2_RandomRays, TheHitLiesOnThePlaneWithinTheInterval) {
  gi::Rng rng(202);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const gi::Plane plane{random_vector(rng, 3), gi::normalize(random_vector(rng, 1) + vec3(0, 0, 1e-3)), 2};
    const Ray ray{random_vector(rng, 5), random_vector(rng, 2), 0.1 * rng.uniform(), 1 + 5 * rng.uniform()};
    const double s_min = gi::dot(ray.at(ray.t_min) - plane.point, plane.normal);
    const double s_max = gi::dot(ray.at(ray.t_max) - plane.point, plane.normal);
    if (std::abs(s_min) < 1e-6 || std::abs(s_max) < 1e-6) continue;
    const auto hit = gi::intersect(ray, plane);
    ASSERT_EQ(hit.has_value(), (s_min < 0) != (s_max < 0))
        << "the ray's segment from t_min to t_max " << ((s_min < 0) != (s_max < 0) ? "crosses" : "does not cross")
        << " the plane: its ends are on " << ((s_min < 0) != (s_max < 0) ? "opposite sides" : "the same side")
        << " (random ray " << k << ")";
    if (!hit) continue;
    ++hits;
    ASSERT_NEAR(gi::dot(hit->point - plane.point, plane.normal), 0, 1e-9)
        << "the hit point must lie on the plane (random ray " << k << ")";
    ASSERT_NEAR(gi::length(hit->point - ray.at(hit->t)), 0, 1e-9) << "the hit point is ray.at(t) (random ray " << k << ")";
  }
  EXPECT_GT(hits, 100) << "the random rays should hit often enough to test something";
}
