#include "gi/raytrace/optics.hpp"

#include <gtest/gtest.h>

using gi::vec3;

namespace {
vec3 direction_at_angle(double degrees) {  // in the x-y plane, heading down onto y = 0
  const double a = degrees * gi::pi / 180;
  return {std::sin(a), -std::cos(a), 0};
}
const vec3 up{0, 1, 0};
}  // namespace

TEST(Reflect, MirrorsAboutTheNormal) {
  const vec3 r = gi::reflect(gi::normalize(vec3(1, -1, 0)), up);
  EXPECT_NEAR(gi::length(r - gi::normalize(vec3(1, 1, 0))), 0, 1e-15);
  EXPECT_EQ(gi::reflect(vec3(0, -1, 0), up), vec3(0, 1, 0));
}

TEST(Refract, ObeysSnellsLaw) {
  for (double degrees : {0.0, 10.0, 30.0, 45.0, 60.0, 89.0}) {
    const vec3 d = direction_at_angle(degrees);
    const auto t = gi::refract(d, up, 1.0 / 1.5);
    ASSERT_TRUE(t) << degrees;
    EXPECT_NEAR(gi::length(*t), 1.0, 1e-12);
    EXPECT_LT(t->y, 0) << "the transmitted ray continues into the surface";
    const double sin_i = d.x, sin_t = t->x;
    EXPECT_NEAR(1.0 * sin_i, 1.5 * sin_t, 1e-12) << degrees;
  }
}

TEST(Refract, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double critical = std::asin(1.0 / 1.5) * 180 / gi::pi;  // 41.81 degrees, glass to air
  EXPECT_TRUE(gi::refract(direction_at_angle(critical - 0.01), up, 1.5));
  EXPECT_FALSE(gi::refract(direction_at_angle(critical + 0.01), up, 1.5));
}

TEST(Fresnel, NormalIncidenceAndGrazing) {
  EXPECT_NEAR(gi::fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-12);  // ((n-1)/(n+1))^2
  EXPECT_NEAR(gi::fresnel_dielectric(1.0, 1.5, 1.0), 0.04, 1e-12);  // same from inside
  EXPECT_NEAR(gi::fresnel_dielectric(0.0, 1.0, 1.5), 1.0, 1e-12);
  EXPECT_NEAR(gi::fresnel_schlick(1.0, 1.0, 1.5), 0.04, 1e-12);
  EXPECT_NEAR(gi::fresnel_schlick(0.0, 1.0, 1.5), 1.0, 1e-12);
}

TEST(Fresnel, BrewsterAngleAndTotalInternalReflection) {
  // At Brewster's angle tan(theta) = n the p-polarised part vanishes:
  // F = r_s^2 / 2, and with theta_i + theta_t = 90 degrees r_s = (1 - n^2) / (1 + n^2).
  const double brewster = std::atan(1.5);
  const double r_s = (1.5 * 1.5 - 1) / (1.5 * 1.5 + 1);
  EXPECT_NEAR(gi::fresnel_dielectric(std::cos(brewster), 1.0, 1.5), 0.5 * r_s * r_s, 1e-12);
  const double critical = std::asin(1.0 / 1.5);
  EXPECT_DOUBLE_EQ(gi::fresnel_dielectric(std::cos(critical + 1e-6), 1.5, 1.0), 1.0);
  EXPECT_LT(gi::fresnel_dielectric(std::cos(critical - 1e-3), 1.5, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(gi::fresnel_schlick(std::cos(critical + 1e-6), 1.5, 1.0), 1.0);
}

TEST(Fresnel, SchlickStaysCloseToTheExactCurve) {
  double worst = 0;
  for (int i = 0; i <= 90; ++i) {
    const double c = std::cos(i * gi::pi / 180);
    worst = std::max(worst, std::abs(gi::fresnel_schlick(c, 1.0, 1.5) - gi::fresnel_dielectric(c, 1.0, 1.5)));
  }
  EXPECT_LT(worst, 0.05);  // Schlick's error for glass peaks near grazing, below 5%
}
