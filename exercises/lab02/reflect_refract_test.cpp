// Graded tests of exercises 2.1 (reflection) and 2.2 (refraction). One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "gi/raytrace/optics.hpp"
#include "support/print.hpp"

using gi::vec3;

namespace {
const vec3 up{0, 1, 0};
// A unit direction heading down onto the plane y = 0 at `degrees` from the normal.
vec3 incoming(double degrees) {
  const double a = degrees * gi::pi / 180;
  return {std::sin(a), -std::cos(a), 0};
}

// Straight in, cos_i = cos_t = 1 and t = eta d + (eta - 1) n is d itself, whatever eta:
// a t along d but of another length is a slip in a term, which shows only when eta != 1.
std::string wrong_length_at_normal_incidence(double length, double eta) {
  std::ostringstream why;
  if (std::abs(length - (2 - eta)) < 1e-9)
    why << "t = d + (eta - 1) n: multiply d by eta. ";
  else if (std::abs(length - eta) < 1e-9)
    why << "t = eta d: the normal term is (eta cos_i - cos_t) n, with eta on cos_i. ";
  else
    why << "a factor eta is missing or a sign is wrong in a term of t = eta d + (eta cos_i - cos_t) n. ";
  why << "Straight in the ray goes on straight, but yours has length " << length << ", not 1 (eta = " << eta
      << "): with cos_i = cos_t = 1, t = eta d + (eta - 1) n must be d itself; such a slip shows only when eta != 1";
  return why.str();
}
}  // namespace

TEST(Ex2_1_Reflect, FortyFiveDegrees) {
  const vec3 r = gi::reflect(gi::normalize(vec3(1, -1, 0)), up);
  EXPECT_NEAR(gi::length(r - gi::normalize(vec3(1, 1, 0))), 0, 1e-12)
      << "r = d - 2 (d.n) n: the normal component flips, the tangential one stays";
}

TEST(Ex2_1_Reflect, NormalIncidenceBouncesStraightBack) {
  const vec3 r = gi::reflect(vec3(0, -1, 0), up);
  EXPECT_NEAR(gi::length(r - vec3(0, 1, 0)), 0, 1e-12) << (std::abs(r.y + 1) < 1e-9 ? "the factor 2 is missing"
                                                                                     : "r = d - 2 (d.n) n");
}

TEST(Ex2_1_Reflect, KeepsLengthAndAngle) {
  const vec3 d = gi::normalize(vec3(0.3, -0.8, 0.5));
  const vec3 n = gi::normalize(vec3(0.1, 1, -0.2));
  const vec3 r = gi::reflect(d, n);
  EXPECT_NEAR(gi::length(r), 1.0, 1e-12) << "reflection must keep a unit vector unit";
  EXPECT_NEAR(gi::dot(r, n), -gi::dot(d, n), 1e-12) << "angle of reflection = angle of incidence";
}

TEST(Ex2_2_Refract, NormalIncidencePassesStraightThrough) {
  const double eta = 1.0 / 1.5;
  const auto t = gi::refract(vec3(0, -1, 0), up, eta);
  ASSERT_TRUE(t) << "straight into glass there is no total internal reflection: return the direction";
  const bool along_d = t->x == 0 && t->z == 0 && t->y < 0;
  EXPECT_NEAR(gi::length(*t - vec3(0, -1, 0)), 0, 1e-12)
      << (t->y > 0  ? "the transmitted ray turned back: check the sign of the (eta cos_i - cos_t) n term"
          : along_d ? wrong_length_at_normal_incidence(gi::length(*t), eta)
                    : "at normal incidence the ray is not bent");
}

TEST(Ex2_2_Refract, ObeysSnellsLawIntoGlass) {
  for (double degrees : {15.0, 30.0, 60.0, 80.0}) {
    const auto t = gi::refract(incoming(degrees), up, 1.0 / 1.5);
    ASSERT_TRUE(t) << "air to glass never reflects totally (" << degrees << " degrees)";
    EXPECT_NEAR(gi::length(*t), 1.0, 1e-9)
        << "the transmitted direction must be unit length (|t| = " << gi::length(*t) << " at " << degrees
        << " degrees): t = eta d + (eta cos_i - cos_t) n is unit only with sin^2(theta_t) = eta^2 (1 - cos_i^2) "
           "and cos_t = sqrt(1 - sin^2(theta_t))";
    EXPECT_LT(t->y, 0) << "the transmitted ray goes on into the surface; check the sign of the n term";
    const double sin_t = t->x;
    const double sin_i = std::sin(degrees * gi::pi / 180);
    EXPECT_NEAR(sin_t, sin_i / 1.5, 1e-9)
        << (std::abs(sin_t - 1.5 * sin_i) < 1e-6 ? "the ray bends away from the normal: eta is eta_i / eta_t, not its inverse"
                                                 : "Snell's law: sin(theta_t) = eta sin(theta_i)");
  }
}

TEST(Ex2_2_Refract, GlassToAirBendsAwayFromTheNormal) {
  const auto t = gi::refract(incoming(30), up, 1.5);
  ASSERT_TRUE(t) << "30 degrees is below the critical angle of 41.8 degrees";
  EXPECT_NEAR(t->x, 1.5 * 0.5, 1e-9) << "sin(theta_t) = 1.5 sin(30 degrees) = 0.75";
}

TEST(Ex2_2_Refract, TotalInternalReflectionPastTheCriticalAngle) {
  const double critical = std::asin(1.0 / 1.5) * 180 / gi::pi;  // 41.81 degrees
  const auto beyond = gi::refract(incoming(critical + 0.5), up, 1.5);
  EXPECT_FALSE(beyond) << "past the critical angle sin(theta_t) > 1: return std::nullopt (total internal reflection)"
                       << (beyond && std::isnan(beyond->x) ? "; you returned NaN from sqrt of a negative number" : "");
  EXPECT_TRUE(gi::refract(incoming(critical - 0.5), up, 1.5)) << "just below the critical angle light still escapes";
}
