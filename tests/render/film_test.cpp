#include "gi/render/film.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "gi/render/render_pass.hpp"

using gi::Color;

namespace {

const gi::Camera camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45};

// One uniform number per sample, from the pixel's stream; the centre sampler draws
// nothing, so these are the stream's numbers in order.
const auto uniform_sample = [](const gi::Ray&, gi::PixelSample& s) { return Color(s.rng.uniform()); };

}  // namespace

TEST(Film, WelfordGivesTheTwoPassVarianceOfEachPixelsSamples) {
  gi::Film film = gi::make_film(5, 4, 7);
  const int passes = 9;
  for (int k = 0; k < passes; ++k) gi::render_pass(film, camera, {}, uniform_sample, 1);
  ASSERT_EQ(film.samples, passes);
  const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
  for (std::size_t i = 0; i < film.sum.size(); ++i) {
    // The same numbers again, from a stream seeded as the film's pixel i is.
    gi::Rng rng(7, i);
    double x[passes], sum = 0;
    for (double& v : x) sum += v = rng.uniform();
    const double m = sum / passes;
    double squares = 0;
    for (double v : x) squares += (v - m) * (v - m);
    EXPECT_FLOAT_EQ(mean.pixels[i].x, float(m)) << i;
    EXPECT_FLOAT_EQ(variance.pixels[i].x, float(squares / (passes - 1) / passes)) << i;
  }
}

TEST(Film, APassContinuesEveryPixelsStream) {
  // Were each pass to start a pixel's stream afresh, its samples would all be equal
  // and its spread 0.
  gi::Film film = gi::make_film(3, 3, 1);
  gi::render_pass(film, camera, {}, uniform_sample, 1);
  gi::render_pass(film, camera, {}, uniform_sample, 2);
  for (const gi::Pixel& v : gi::film_variance(film).pixels) EXPECT_GT(v.x, 0);
}

TEST(Film, TheMeanVarianceOfUniformSamplesIsATwelfthOverN) {
  // Var(mean of N uniforms) = 1 / (12 N). Over 4096 pixels the estimates' mean has a
  // relative standard error of about sqrt(2 / ((N - 1) 4096)) = 0.6% at N = 16: 5% is
  // eight of them (a false failure far below one in a million).
  gi::Film film = gi::make_film(64, 64, 3);
  for (int k = 0; k < 16; ++k) gi::render_pass(film, camera, {}, uniform_sample, 0);
  double mean_variance = 0;
  for (const gi::Pixel& v : gi::film_variance(film).pixels) mean_variance += v.x / 4096;
  EXPECT_NEAR(mean_variance, 1.0 / (12 * 16), 0.05 / (12 * 16));
  const gi::Image se = gi::film_standard_error(film);
  EXPECT_FLOAT_EQ(se.pixels[5].x, std::sqrt(gi::film_variance(film).pixels[5].x));
}

TEST(Film, SamplesThatAreNotNumbersCountAsZeroAndAreReported) {
  gi::Film film = gi::make_film(4, 2, 1);
  const auto sometimes_nan = [](const gi::Ray&, gi::PixelSample& s) {
    return s.x == 1 ? Color(std::numeric_limits<double>::quiet_NaN()) : Color(2.0);
  };
  gi::render_pass(film, camera, {gi::Sampler::Grid, 2}, sometimes_nan, 1);
  EXPECT_EQ(film.discarded, 2 * 4);  // two pixels of column 1, four samples each
  const gi::Image mean = gi::film_mean(film);
  EXPECT_EQ(mean.at(1, 0).x, 0.0f);
  EXPECT_EQ(mean.at(0, 0).x, 2.0f);
}

TEST(Film, SizesOutOfRangeAreRefused) {
  EXPECT_THROW(gi::make_film(0, 10, 1), std::invalid_argument);
  EXPECT_THROW(gi::make_film(10, 20000, 1), std::invalid_argument);
  const gi::Film empty = gi::make_film(2, 2, 1);
  EXPECT_EQ(gi::film_mean(empty).pixels[0], gi::Pixel(0));
  EXPECT_EQ(gi::film_variance(empty).pixels[0], gi::Pixel(0));
}
