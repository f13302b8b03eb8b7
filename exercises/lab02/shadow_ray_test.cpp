// Graded tests of exercise 2.5: the shadow ray. One point per test.
// The occluders are quads, whose intersection is given, so this lab does not
// depend on your lab 1 code.
#include <gtest/gtest.h>

#include <string>

#include "gi/core/rng.hpp"
#include "gi/raytrace/shading.hpp"
#include "support/print.hpp"

using gi::vec3;

namespace {
gi::World scene_with(const std::vector<gi::Quad>& quads) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  for (gi::Quad q : quads) {
    q.material = m;
    scene.add(q);
  }
  // Brute force, not the BVH: this lab must not depend on your lab 5 code.
  return gi::make_world(scene, gi::Acceleration::BruteForce);
}
const double epsilon = 1e-6;
}  // namespace

TEST(Ex2_5_ShadowRay, DirectionIsUnitTowardsTheLight) {
  const gi::Ray ray = gi::shadow_ray({1, 0, 0}, {0, 1, 0}, {1, 8, 6}, epsilon);
  EXPECT_NEAR(gi::length(ray.direction), 1.0, 1e-9) << "normalise the direction to the light";
  const double offset = gi::length(ray.origin - vec3(1, 0, 0));
  EXPECT_NEAR(gi::dot(ray.direction, gi::normalize(vec3(0, 8, 6))), 1.0, 1e-6)
      << (offset > 10 * epsilon
              ? "the ray starts " + testing::PrintToString(offset) + " from the surface point (at " +
                    testing::PrintToString(ray.origin) + "), so from there the light lies in another direction: "
                    "offset the origin by epsilon = 1e-6 along the normal, not more"
              : std::string("point the ray at the light: direction = (light - origin) / |light - origin|"));
}

TEST(Ex2_5_ShadowRay, StartsJustOffTheSurface) {
  const gi::Ray ray = gi::shadow_ray({1, 0, 0}, {0, 1, 0}, {1, 8, 6}, epsilon);
  EXPECT_GT(ray.origin.y, 0.5 * epsilon) << "move the origin epsilon along the normal, or the ray can hit its own "
                                            "surface through round-off (shadow acne)";
  EXPECT_LT(gi::length(ray.origin - vec3(1, 0, 0)), 10 * epsilon) << "offset by epsilon, not more";
}

TEST(Ex2_5_ShadowRay, StopsAtTheLight) {
  const gi::Ray ray = gi::shadow_ray({0, 0, 0}, {0, 1, 0}, {0, 5, 0}, epsilon);
  EXPECT_NEAR(ray.at(ray.t_max).y, 5.0, 1e-3) << "t_max must be the distance to the light (minus epsilon)";
  EXPECT_LE(ray.at(ray.t_max).y, 5.0) << "the ray must end before the light, not beyond it";
}

TEST(Ex2_5_ShadowRay, OnlyObjectsBetweenPointAndLightShadow) {
  const gi::Quad between{{-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, 0};   // y = 2, under the light at y = 5
  const gi::Quad beyond{{-1, 7, -1}, {0, 0, 2}, {2, 0, 0}, 0};    // y = 7, above the light
  EXPECT_FALSE(gi::visible(scene_with({between}), {0, 0, 0}, {0, 1, 0}, {0, 5, 0}, epsilon))
      << "a quad between the point and the light casts a shadow";
  EXPECT_TRUE(gi::visible(scene_with({beyond}), {0, 0, 0}, {0, 1, 0}, {0, 5, 0}, epsilon))
      << "a quad beyond the light must not cast a shadow: limit the shadow ray with t_max";
}

TEST(Ex2_5_ShadowRay, NoShadowAcne) {
  // Points on a tilted quad, computed the way the tracer computes hit points:
  // each carries round-off of ~1e-16, so a shadow ray started exactly there finds
  // its own quad again at t ~ 0 about half the time.
  const gi::Quad wall{{0.1, 0.2, 0.3}, {1.7, 0.3, -0.2}, {0.4, 1.1, 1.3}, 0};
  const gi::World scene = scene_with({wall});
  const vec3 n = gi::normal(wall);
  gi::Rng rng(5, 5);
  int shadowed = 0;
  for (int i = 0; i < 1000; ++i) {
    const vec3 p = wall.corner + rng.uniform() * wall.edge_u + rng.uniform() * wall.edge_v;
    shadowed += !gi::visible(scene, p, n, p + 3.0 * n + vec3(0.3, 0.2, 0.1), epsilon);
  }
  EXPECT_EQ(shadowed, 0) << shadowed << " of 1000 lit points found their own surface: start the shadow ray "
                         << "epsilon off the surface (shadow acne)";
}

TEST(Ex2_5_ShadowRay, StartsOnTheLightsSide) {
  // Light behind the quad's normal (the back of a two-sided surface, e.g. glass).
  const gi::Ray ray = gi::shadow_ray({0, 0, 0}, {0, 1, 0}, {0, -5, 0}, epsilon);
  EXPECT_LT(ray.origin.y, 0) << "offset the origin towards the side the light is on, or the ray starts behind its "
                                "own surface";
}
