// Graded tests of exercises 11.1 (a shot) and 11.2 (the ambient term). One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "gi/radiosity/system/progressive.hpp"
#include "support/print.hpp"

using gi::Color;

namespace {
// Three elements; the shooter is patch {element 0} of area 2.
const std::vector<double> area = {2.0, 1.0, 4.0};
const std::vector<Color> rho = {Color(0.5), Color(0.8, 0.4, 0.2), Color(0.6)};
gi::Patch patch_of(int element) {
  return gi::Patch{gi::Polygon{{}, {}, {}, area[element]}, 0, element, 1};
}
}  // namespace

TEST(Ex11_1_Shot, ReceiverGetsItsShareByReciprocity) {
  std::vector<Color> B = {Color(1.0), Color(0.0), Color(0.0)}, unshot = B;
  gi::shoot(patch_of(0), {0.0, 0.3, 0.1}, area, rho, B, unshot);
  // dB_1 = rho_1 dB_0 F_01 A_0 / A_1 = 0.8 * 1 * 0.3 * 2 / 1.
  EXPECT_NEAR(B[1].x, 0.48, 1e-12) << "receivers get rho_j dB_p F_pj A_p / A_j: F_jp by reciprocity";
  EXPECT_NEAR(B[2].x, 0.6 * 0.1 * 2.0 / 4.0, 1e-12) << "the area ratio A_p / A_j matters: here 1/2";
}

TEST(Ex11_1_Shot, ReceivedLightIsAlsoUnshot) {
  std::vector<Color> B = {Color(1.0), Color(0.5), Color(0.0)}, unshot = {Color(1.0), Color(0.0), Color(0.0)};
  gi::shoot(patch_of(0), {0.0, 0.3, 0.1}, area, rho, B, unshot);
  EXPECT_NEAR(unshot[1].x, 0.48, 1e-12) << "what j receives it must shoot later: add it to j's unshot too";
  EXPECT_NEAR(B[1].x, 0.5 + 0.48, 1e-12) << "add to B_j, do not overwrite it";
}

TEST(Ex11_1_Shot, TheShooterIsCleared) {
  std::vector<Color> B = {Color(1.0), Color(0.0), Color(0.0)}, unshot = B;
  gi::shoot(patch_of(0), {0.0, 0.3, 0.1}, area, rho, B, unshot);
  EXPECT_EQ(unshot[0], Color(0.0)) << "after shooting, the patch's unshot radiosity is zero -- or it shoots again";
  EXPECT_EQ(B[0], Color(1.0)) << "its radiosity B stays";
}

TEST(Ex11_1_Shot, ChannelsAreShotSeparately) {
  std::vector<Color> B = {Color(1.0, 2.0, 4.0), Color(0.0), Color(0.0)}, unshot = B;
  gi::shoot(patch_of(0), {0.0, 0.5, 0.0}, area, rho, B, unshot);
  EXPECT_NEAR(B[1].y, 0.4 * 2.0 * 0.5 * 2.0, 1e-12) << "green: rho_j.y dB_p.y F_pj A_p / A_j, channel by channel";
  EXPECT_NEAR(B[1].z, 0.2 * 4.0 * 0.5 * 2.0, 1e-12) << "blue: rho_j.z dB_p.z F_pj A_p / A_j, channel by channel";
}

TEST(Ex11_1_Shot, APatchShootsTheMeanOfItsElements) {
  // Patch = elements 1 and 2 (area 5): its unshot is (1 * 1 + 4 * 0.5) / 5 = 0.6.
  std::vector<Color> B = {Color(0.0), Color(1.0), Color(0.5)}, unshot = B;
  const gi::Patch patch{gi::Polygon{{}, {}, {}, 5.0}, 0, 1, 2};
  gi::shoot(patch, {0.2, 0.0, 0.0}, area, rho, B, unshot);
  EXPECT_NEAR(B[0].x, 0.5 * 0.6 * 0.2 * 5.0 / 2.0, 1e-12) << "the area-weighted mean of the patch's elements";
  EXPECT_EQ(unshot[1], Color(0.0)) << "every element of the shooting patch is cleared";
  EXPECT_EQ(unshot[2], Color(0.0)) << "every element of the shooting patch is cleared";
}

TEST(Ex11_2_Ambient, NothingUnshotNoAmbient) {
  EXPECT_EQ(gi::ambient_term(area, rho, std::vector<Color>(3, Color(0.0))), Color(0.0))
      << "with nothing left unshot the ambient term is 0: the picture is finished";
}

TEST(Ex11_2_Ambient, AreaWeightedUnshotTimesInterreflection) {
  // Unshot power 2*1 + 1*0 + 4*0.5 = 4 over area 7; rho_avg = (2*.5 + 1*.8 + 4*.6) / 7.
  const Color a = gi::ambient_term(area, rho, {Color(1.0), Color(0.0), Color(0.5)});
  const double rho_avg = (2 * 0.5 + 1 * 0.8 + 4 * 0.6) / 7, unshot = 4.0 / 7;
  // What the usual slips give, to say which one it is.
  const double plain_rho = (0.5 + 0.8 + 0.6) / 3, plain_unshot = 1.5 / 3;
  const std::pair<double, const char*> slips[] = {
      {unshot, "R_total is missing: the unshot light goes on reflecting, 1 + rho + rho^2 + ... = 1 / (1 - rho_avg)"},
      {unshot * (1 + rho_avg), "R_total = 1 + rho_avg counts one bounce only: the series sums to 1 / (1 - rho_avg)"},
      {unshot * rho_avg / (1 - rho_avg), "R_total = 1 / (1 - rho_avg), not rho_avg / (1 - rho_avg)"},
      {4.0 / (1 - rho_avg), "divide the unshot power by the total area: the ambient term is a radiosity"},
      {plain_unshot / (1 - plain_rho), "weight the unshot radiosity and the reflectance by the elements' areas"},
      {plain_unshot / (1 - rho_avg), "weight the unshot radiosity by the elements' areas: sum dB_i A_i / sum A_i"},
      {unshot / (1 - plain_rho), "the average reflectance is area-weighted: sum rho_i A_i / sum A_i"}};
  const char* why = "ambient = R_total * sum dB_i A_i / sum A_i with R_total = 1 / (1 - rho_avg), rho_avg area-weighted";
  for (const auto& [value, what] : slips)
    if (std::abs(a.x - value) < 1e-12) why = what;
  EXPECT_NEAR(a.x, unshot / (1 - rho_avg), 1e-12) << why;
}

TEST(Ex11_2_Ambient, PerChannel) {
  const Color a = gi::ambient_term(area, rho, {Color(1.0), Color(0.0), Color(0.5)});
  const double rho_avg_z = (2 * 0.5 + 1 * 0.2 + 4 * 0.6) / 7;
  EXPECT_NEAR(a.z, 4.0 / 7 / (1 - rho_avg_z), 1e-12) << "the blue channel has its own average reflectance";
}

TEST(Ex11_2_Ambient, ExactForAFurnaceAtTheStart) {
  // Uniform rho, all of E still unshot: B + rho * ambient is exactly E / (1 - rho).
  const std::vector<double> a = {1, 1, 1, 1};
  const std::vector<Color> r(4, Color(0.6)), e(4, Color(1.0));
  const std::vector<Color> shown = gi::with_ambient(a, r, e, e);
  EXPECT_NEAR(shown[0].x, 1.0 / 0.4, 1e-12)
      << "a furnace with rho = 0.6 and E = 1: E + rho * ambient = 1 + 0.6 / 0.4 = E / (1 - rho), the converged value";
}
