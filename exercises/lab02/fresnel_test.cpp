// Graded tests of exercise 2.3: Fresnel reflectance of a dielectric. One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gi/raytrace/optics.hpp"
#include "support/print.hpp"

TEST(Ex2_3_Fresnel, NormalIncidence) {
  EXPECT_NEAR(gi::fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-9) << "at 0 degrees F = ((n1 - n2) / (n1 + n2))^2 = 0.04";
  EXPECT_NEAR(gi::fresnel_dielectric(1.0, 1.5, 1.0), 0.04, 1e-9) << "the same from inside the glass";
}

TEST(Ex2_3_Fresnel, GrazingIncidenceReflectsEverything) {
  EXPECT_NEAR(gi::fresnel_dielectric(0.0, 1.0, 1.5), 1.0, 1e-9) << "at 90 degrees F = 1";
}

TEST(Ex2_3_Fresnel, ExactValueAtSixtyDegrees) {
  // cos_i = 0.5, sin_t = sin(60)/1.5, r_s = -0.42, r_p = -0.042: F = 0.0892 (Schlick gives 0.0700)
  const double ci = 0.5;
  const double ct = std::sqrt(1 - 0.75 / 2.25);
  const double rs = (ci - 1.5 * ct) / (ci + 1.5 * ct);
  const double rp = (1.5 * ci - ct) / (1.5 * ci + ct);
  const double f = gi::fresnel_dielectric(ci, 1.0, 1.5);
  EXPECT_NEAR(f, 0.5 * (rs * rs + rp * rp), 1e-9) << [&]() -> std::string {
    const std::string got = " (got F = " + testing::PrintToString(f) + ", want " +
                            testing::PrintToString(0.5 * (rs * rs + rp * rp)) + ")";
    if (std::abs(f - gi::fresnel_schlick(ci, 1.0, 1.5)) < 1e-6)
      return "that is Schlick's approximation; the exercise is the exact Fresnel equations" + got;
    if (std::abs(f - 1.0) < 1e-9)
      return "F = 1 at 60 degrees from air into glass, as if totally reflected: Snell's law gives sin_t = (eta_i / "
             "eta_t) sin_i = sin 60 / 1.5 = 0.577; the ratio upside down, eta_t / eta_i, gives 1.3 > 1" + got;
    if (std::abs(f - rs * rs) < 1e-9)
      return "F = r_s^2 alone: r_p is missing or written like r_s; r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + "
             "eta_i cos_t) = " + testing::PrintToString(rp) + " here, r_s = " + testing::PrintToString(rs) + got;
    return "F = (r_s^2 + r_p^2) / 2, the average of the two polarisations (squared amplitudes)" + got;
  }();
}

TEST(Ex2_3_Fresnel, BrewsterAngleHasNoPPolarisedReflection) {
  const double brewster = std::atan(1.5);
  const double rs = (1.5 * 1.5 - 1) / (1.5 * 1.5 + 1);
  EXPECT_NEAR(gi::fresnel_dielectric(std::cos(brewster), 1.0, 1.5), 0.5 * rs * rs, 1e-9)
      << "at Brewster's angle r_p = 0; check the r_p formula (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)";
}

TEST(Ex2_3_Fresnel, TotalInternalReflection) {
  const double critical = std::asin(1.0 / 1.5);
  const double f = gi::fresnel_dielectric(std::cos(critical + 0.05), 1.5, 1.0);
  EXPECT_EQ(f, 1.0) << "inside glass past the critical angle all light is reflected: return 1 (got " << f << ")";
}

TEST(Ex2_3_Fresnel, StaysBetweenZeroAndOne) {
  for (int i = 0; i <= 90; ++i) {
    const double c = std::cos(i * gi::pi / 180);
    for (auto [a, b] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 2.4}}) {
      const double f = gi::fresnel_dielectric(c, a, b);
      ASSERT_TRUE(f >= 0 && f <= 1) << "F = " << f << " at " << i << " degrees from index " << a << " to " << b;
    }
  }
}
