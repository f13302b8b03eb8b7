// The Cornell box's palette comes from the published spectra: the band means are
// checked against the trapezoid rule done by hand on small spectra, and the box's
// numbers against the data page's (www.graphics.cornell.edu/online/box/data.html).
#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/scene/cornell_box.hpp"
#include "gi/scene/cornell_spectra.hpp"

namespace {

TEST(BandMean, ExactForPiecewiseLinearSpectra) {
  // s = 0 at 400, 8 at 500, 15.6 at 600, 18.4 at 700: each band is one trapezoid.
  const gi::Spectrum light = gi::cornell_light_spectrum();
  EXPECT_NEAR(gi::band_mean(light, 400, 500), 4.0, 1e-12);
  EXPECT_NEAR(gi::band_mean(light, 500, 600), 11.8, 1e-12);
  EXPECT_NEAR(gi::band_mean(light, 600, 700), 17.0, 1e-12);
  // A band that cuts samples: s(450) = 4, s(550) = 11.8, mean over [450, 550] is
  // (50 (4 + 8) / 2 + 50 (8 + 11.8) / 2) / 100 = 7.95.
  EXPECT_NEAR(gi::band_mean(light, 450, 550), 7.95, 1e-12);
  // The whole range is the mean of the three bands (equal widths).
  EXPECT_NEAR(gi::band_mean(light, 400, 700), (4.0 + 11.8 + 17.0) / 3, 1e-12);
}

TEST(BandMean, RefusesBandsOutsideTheData) {
  const gi::Spectrum light = gi::cornell_light_spectrum();
  EXPECT_THROW(gi::band_mean(light, 380, 500), std::invalid_argument);
  EXPECT_THROW(gi::band_mean(light, 600, 720), std::invalid_argument);
  EXPECT_THROW(gi::band_mean(light, 500, 500), std::invalid_argument);
  EXPECT_THROW(gi::band_mean(gi::Spectrum{{400}, {1}}, 400, 400), std::invalid_argument);
}

TEST(CornellSpectra, SeventySixSamplesFrom400To700) {
  for (const gi::Spectrum& s : {gi::cornell_white_spectrum(), gi::cornell_red_spectrum(), gi::cornell_green_spectrum()}) {
    ASSERT_EQ(s.wavelength_nm.size(), 76u);
    ASSERT_EQ(s.value.size(), 76u);
    EXPECT_EQ(s.wavelength_nm.front(), 400);
    EXPECT_EQ(s.wavelength_nm.back(), 700);
    for (double v : s.value) EXPECT_TRUE(v > 0 && v < 1) << v;
  }
  // Spot values from the data page's table.
  EXPECT_EQ(gi::cornell_white_spectrum().value[0], 0.343);
  EXPECT_EQ(gi::cornell_red_spectrum().value[50], 0.287);    // 600 nm
  EXPECT_EQ(gi::cornell_green_spectrum().value[75], 0.159);  // 700 nm
}

// The band means computed independently (the trapezoid rule, a few lines of Python
// over the data page's table), to five decimals.
TEST(CornellPalette, PublishedBandMeans) {
  const gi::CornellPalette p = gi::cornell_palette();
  auto expect = [](const gi::Color& c, double r, double g, double b) {
    EXPECT_NEAR(c.x, r, 5e-6);
    EXPECT_NEAR(c.y, g, 5e-6);
    EXPECT_NEAR(c.z, b, 5e-6);
  };
  expect(p.white, 0.73374, 0.73566, 0.70592);
  expect(p.red, 0.58054, 0.08778, 0.05660);
  expect(p.green, 0.13186, 0.34834, 0.11746);
  expect(p.light_exitance / gi::pi, 17.0, 11.8, 4.0);  // radiance L, E = pi L
  expect(p.light_reflectance, 0, 0, 0);
}

TEST(CornellPalette, NamedOptions) {
  gi::CornellPaletteChoice choice;
  choice.reflectances = gi::CornellReflectances::McGuire;
  choice.light = gi::CornellLight::WhiteUnitExitance;
  choice.light_reflects = true;
  const gi::CornellPalette p = gi::cornell_palette(choice);
  EXPECT_EQ(p.white, gi::Color(0.725, 0.71, 0.68));
  EXPECT_EQ(p.red, gi::Color(0.63, 0.065, 0.05));
  EXPECT_EQ(p.green, gi::Color(0.14, 0.45, 0.091));
  EXPECT_EQ(p.light_exitance, gi::Color(1.0));
  EXPECT_EQ(p.light_reflectance, gi::Color(0.78));
}

// The box takes every colour from the palette it is given: one place for the data.
TEST(CornellPalette, TheBoxUsesIt) {
  gi::CornellPaletteChoice choice;
  choice.reflectances = gi::CornellReflectances::McGuire;
  const gi::CornellPalette p = gi::cornell_palette(choice);
  const gi::CornellBox box = gi::cornell_box_data(gi::CornellContents::Blocks, false, p);
  int lights = 0;
  for (const gi::QuadSurface& s : box.surfaces) {
    if (s.name == "light") {
      ++lights;
      EXPECT_EQ(s.exitance, p.light_exitance);
      EXPECT_EQ(s.reflectance, p.light_reflectance);
    } else {
      EXPECT_EQ(s.exitance, gi::Color(0.0)) << s.name;
      EXPECT_TRUE(s.reflectance == p.white || s.reflectance == p.red || s.reflectance == p.green) << s.name;
    }
  }
  EXPECT_EQ(lights, 1);
}

}  // namespace
