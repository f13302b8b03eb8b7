// Graded tests of exercise 2.4: Phong shading. One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/raytrace/shading.hpp"
#include "support/print.hpp"

using gi::Color;
using gi::vec3;

namespace {
gi::Material plastic() {
  gi::Material m;
  m.diffuse = Color(0.6, 0.4, 0.2);
  m.specular = Color(0.3);
  m.shininess = 20;
  return m;
}
vec3 at_angle(double degrees) {  // unit vector in the x-y plane, `degrees` from +y towards +x
  const double a = degrees * gi::pi / 180;
  return {std::sin(a), std::cos(a), 0};
}
const vec3 n{0, 1, 0};
}  // namespace

TEST(Ex2_4_Phong, DiffuseTermFollowsTheCosine) {
  gi::Material m = plastic();
  m.specular = Color(0);
  const Color c = gi::phong(m, m.diffuse, n, at_angle(60), n, Color(2.0));
  EXPECT_NEAR(c.x, 2.0 * 0.6 * 0.5, 1e-9) << "I_l k_d (N.L): cos 60 = 0.5";
  EXPECT_NEAR(c.z, 2.0 * 0.2 * 0.5, 1e-9) << "each channel uses its own k_d";
}

TEST(Ex2_4_Phong, UsesTheTexturedDiffuseColour) {
  gi::Material m = plastic();
  m.specular = Color(0);
  const Color c = gi::phong(m, Color(1, 0, 0), n, n, n, Color(1));
  EXPECT_NEAR(c.x, 1.0, 1e-9) << "use the kd argument (the colour after texturing), not material.diffuse";
  EXPECT_NEAR(c.y, 0.0, 1e-9) << "kd = (1, 0, 0) has no green: use the kd argument";
}

TEST(Ex2_4_Phong, HighlightAtTheMirrorDirection) {
  const gi::Material m = plastic();
  const Color c = gi::phong(m, m.diffuse, n, at_angle(-40), at_angle(40), Color(1));
  EXPECT_NEAR(c.x, 0.6 * std::cos(40 * gi::pi / 180) + 0.3, 1e-9)
      << "when V is the mirror direction R of L, (R.V)^n = 1 and the highlight adds k_s in full";
}

TEST(Ex2_4_Phong, HighlightFallsOffAsCosineToTheShininess) {
  const gi::Material m = plastic();
  const Color c = gi::phong(m, m.diffuse, n, at_angle(-40), at_angle(10), Color(1));
  const double diffuse = 0.6 * std::cos(40 * gi::pi / 180);
  const double expected = diffuse + 0.3 * std::pow(std::cos(30 * gi::pi / 180), 20);
  // Blinn's half-vector form gives (N.H)^n = cos(15 deg)^20 here instead.
  const double blinn = diffuse + 0.3 * std::pow(std::cos(15 * gi::pi / 180), 20);
  EXPECT_NEAR(c.x, expected, 1e-9) << (std::abs(c.x - blinn) < 1e-6
                                           ? "that is Blinn-Phong (N.H)^n; the lecture's Phong model uses (R.V)^n"
                                           : "k_s (R.V)^n with R the reflection of L about N");
}

TEST(Ex2_4_Phong, TheLightsIntensityScalesBothTerms) {
  const gi::Material m = plastic();
  const Color intensity(2.0, 1.0, 0.5);
  const Color c = gi::phong(m, m.diffuse, n, at_angle(-40), at_angle(40), intensity);
  const double cos40 = std::cos(40 * gi::pi / 180);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(c[k], intensity[k] * (m.diffuse[k] * cos40 + 0.3), 1e-9)
        << "channel " << k << ": I_l [k_d (N.L) + k_s (R.V)^n] -- the light's intensity multiplies the diffuse "
        << "term and the highlight alike, channel by channel";
}

TEST(Ex2_4_Phong, NoHighlightWhenRDotVIsNegative) {
  gi::Material m = plastic();
  m.shininess = 2;  // an even exponent turns a negative R.V into a positive highlight
  m.diffuse = Color(0);
  const Color c = gi::phong(m, m.diffuse, n, at_angle(-60), at_angle(-70), Color(1));
  EXPECT_NEAR(c.x, 0.0, 1e-9) << "R.V < 0 here: clamp it to 0 before raising it to the power n";
}

TEST(Ex2_4_Phong, LightBehindTheSurfaceContributesNothing) {
  const gi::Material m = plastic();
  const Color c = gi::phong(m, m.diffuse, n, at_angle(100), at_angle(-80), Color(1));
  EXPECT_EQ(c, Color(0)) << "N.L < 0: the light is behind the surface -- no diffuse term and no highlight";
}
