#include "gi/raytrace/shading.hpp"

#include <gtest/gtest.h>

using gi::Color;
using gi::vec3;

namespace {
gi::Material plastic() {
  gi::Material m;
  m.diffuse = Color(0.5);
  m.specular = Color(0.25);
  m.shininess = 10;
  return m;
}
}  // namespace

TEST(Phong, DiffuseFollowsLambertsCosine) {
  gi::Material m = plastic();
  m.specular = Color(0);
  const vec3 n{0, 1, 0}, v{0, 1, 0};
  const vec3 l = gi::normalize(vec3(1, 1, 0));  // 45 degrees
  const Color c = gi::phong(m, m.diffuse, n, l, v, Color(2.0));
  EXPECT_NEAR(c.x, 2.0 * 0.5 * std::sqrt(0.5), 1e-12);
}

TEST(Phong, HighlightPeaksAtTheMirrorDirection) {
  const gi::Material m = plastic();
  const vec3 n{0, 1, 0};
  const vec3 l = gi::normalize(vec3(-1, 1, 0));
  const vec3 mirror = gi::normalize(vec3(1, 1, 0));
  const Color at_mirror = gi::phong(m, m.diffuse, n, l, mirror, Color(1));
  EXPECT_NEAR(at_mirror.x, 0.5 * std::sqrt(0.5) + 0.25, 1e-12);
  // 30 degrees off the mirror direction: (cos 30)^10.
  const double a = (45.0 + 30.0) * gi::pi / 180;
  const Color off = gi::phong(m, m.diffuse, n, l, vec3(std::cos(a), std::sin(a), 0), Color(1));
  EXPECT_NEAR(off.x, 0.5 * std::sqrt(0.5) + 0.25 * std::pow(std::cos(gi::pi / 6), 10), 1e-12);
}

TEST(Phong, LightBehindTheSurfaceGivesNothing) {
  const gi::Material m = plastic();
  const Color c = gi::phong(m, m.diffuse, {0, 1, 0}, gi::normalize(vec3(1, -0.1, 0)), {0, 1, 0}, Color(1));
  EXPECT_EQ(c, Color(0));
}

TEST(ShadowRay, StartsOffTheSurfaceAndStopsBeforeTheLight) {
  const gi::Ray ray = gi::shadow_ray({0, 0, 0}, {0, 1, 0}, {0, 10, 0}, 1e-4);
  EXPECT_NEAR(ray.origin.y, 1e-4, 1e-15);
  EXPECT_NEAR(gi::length(ray.direction), 1.0, 1e-15);
  EXPECT_NEAR(ray.t_max, 10.0 - 2e-4, 1e-12);
}

TEST(ShadowRay, OnlyObjectsBetweenPointAndLightCastShadows) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Sphere{{0, 5, 0}, 1, m});
  const gi::World world = gi::make_world(scene);
  EXPECT_FALSE(gi::visible(world, {0, 0, 0}, {0, 1, 0}, {0, 10, 0}, 1e-6));  // blocked
  EXPECT_TRUE(gi::visible(world, {0, 0, 0}, {0, 1, 0}, {0, 3, 0}, 1e-6));    // light before the sphere
  EXPECT_TRUE(gi::visible(world, {3, 0, 0}, {0, 1, 0}, {3, 10, 0}, 1e-6));   // passes beside it
}
