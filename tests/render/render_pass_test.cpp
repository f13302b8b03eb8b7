#include "gi/render/render_pass.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using gi::Color;
using gi::vec2;

namespace {

const gi::Camera camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45};

// Radiance linear in the image position: the box filter's pixel value is then the
// linear function at the pixel's centre, (x + 0.5) + 2 (y + 0.5).
const auto linear = [](const gi::Ray&, gi::PixelSample& s) { return Color(s.position.x + 2 * s.position.y); };

}  // namespace

TEST(RenderPass, EverySamplerAveragesOverThePixel) {
  const auto pixel_value = [](const gi::Sampling& sampling, int passes) {
    gi::Film film = gi::make_film(6, 5, 2);
    for (int k = 0; k < passes; ++k) gi::render_pass(film, camera, sampling, linear, 1);
    return gi::film_mean(film).at(3, 4).x;  // exact: 3.5 + 9
  };
  EXPECT_EQ(pixel_value({gi::Sampler::Centre}, 1), 12.5f);
  EXPECT_FLOAT_EQ(pixel_value({gi::Sampler::Grid, 5}, 1), 12.5f);  // the midpoint rule: exact
  // Over 2000 passes the error of the mean is about sqrt(5/12 / (4 * 2000)) = 0.007 for
  // random, less for jittered; 0.03 is four of those.
  EXPECT_NEAR(pixel_value({gi::Sampler::Random, 2}, 2000), 12.5, 0.03);
  EXPECT_NEAR(pixel_value({gi::Sampler::Jittered, 2}, 2000), 12.5, 0.03);
  EXPECT_FLOAT_EQ(pixel_value({gi::Sampler::Adaptive, 1, 0.1, 2}, 1), 12.5f);  // the corners' mean: exact
}

TEST(RenderPass, EachSampleKnowsItsPixelAndItsNumber) {
  gi::Film film = gi::make_film(40, 35, 1);  // two tiles across, two down
  std::vector<std::vector<long long>> indices(40 * 35);
  int bad = 0;
  const auto record = [&](const gi::Ray&, gi::PixelSample& s) {
    indices[s.y * 40 + s.x].push_back(s.index);
    bad += s.position.x < s.x || s.position.x >= s.x + 1 || s.position.y < s.y ||
           s.position.y >= s.y + 1;
    return Color(0.0);
  };
  EXPECT_EQ(gi::render_tasks(film), 4);
  gi::render_pass(film, camera, {gi::Sampler::Jittered, 2}, record, 1);
  gi::render_pass(film, camera, {gi::Sampler::Jittered, 2}, record, 1);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(film.samples, 8);
  for (const std::vector<long long>& in_pixel : indices)
    EXPECT_EQ(in_pixel, (std::vector<long long>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(RenderPass, AdaptiveSamplesCornersAndSplitsWhereTheyDiffer) {
  gi::Film film = gi::make_film(4, 3, 1);
  int rays = 0;
  const auto counted = [&](const gi::Ray& ray, gi::PixelSample& s) {
    ++rays;
    return linear(ray, s);
  };
  gi::render_pass(film, camera, {gi::Sampler::Adaptive, 1, 0.1, 2}, counted, 1);
  EXPECT_EQ(film.samples, 1);  // one estimate of each pixel
  EXPECT_EQ(rays, 12 * (4 + 5 + 20)) << "a linear ramp differs at every corner: all squares split";
}

// Same seed, same bytes, whatever the thread count: every sampler, over three passes,
// on 1, 2 and 3 threads, with a radiance function that draws a varying number of random
// numbers from the pixel's stream (as a path tracer's paths do). The film's every sum,
// spread and stream agree to the bit; the film is 3 x 2 tiles, the last ones partial.
TEST(RenderPass, SameSeedSameFilmOnOneTwoAndThreeThreads) {
  const auto noisy = [](const gi::Ray& ray, gi::PixelSample& s) {
    Color L = ray.direction;
    while (s.rng.uniform() < 0.6) L += Color(s.rng.uniform(), s.rng.uniform(), 0.0);
    return L;
  };
  for (const gi::Sampling& sampling : {gi::Sampling{gi::Sampler::Centre}, gi::Sampling{gi::Sampler::Grid, 2},
                                       gi::Sampling{gi::Sampler::Random, 2}, gi::Sampling{gi::Sampler::Jittered, 3},
                                       gi::Sampling{gi::Sampler::Adaptive, 1, 0.05, 2}}) {
    std::vector<gi::Film> films;
    for (int threads : {1, 2, 3}) {
      gi::Film film = gi::make_film(70, 41, 9);
      for (int pass = 0; pass < 3; ++pass) gi::render_pass(film, camera, sampling, noisy, threads);
      films.push_back(std::move(film));
    }
    for (int k : {1, 2}) {
      EXPECT_EQ(films[k].sum, films[0].sum) << k + 1 << " threads, sampler " << int(sampling.sampler);
      EXPECT_EQ(films[k].m2, films[0].m2) << k + 1 << " threads, sampler " << int(sampling.sampler);
      EXPECT_EQ(films[k].samples, films[0].samples);
      for (std::size_t i = 0; i < films[0].rng.size(); i += 97) {
        gi::Rng here = films[k].rng[i], there = films[0].rng[i];  // copies: each film's streams stay as they are
        EXPECT_EQ(here.uniform(), there.uniform()) << "pixel " << i << "'s stream";
      }
    }
  }
  // Another seed, another film: the seed is what the pixels draw from.
  gi::Film one = gi::make_film(70, 41, 9), other = gi::make_film(70, 41, 10);
  gi::render_pass(one, camera, {gi::Sampler::Jittered, 3}, noisy, 2);
  gi::render_pass(other, camera, {gi::Sampler::Jittered, 3}, noisy, 2);
  EXPECT_NE(one.sum, other.sum);
}

// The independent sequence is the pixel's own stream, read in the order asked, whatever
// the dimension (a 2D point's second coordinate first): a method that moves from
// sample.rng to get_1d / get_2d keeps its pictures to the bit.
TEST(RenderPass, TheIndependentSequenceIsThePixelsStreamInOrder) {
  const auto by_stream = [](const gi::Ray&, gi::PixelSample& s) {
    const double a = s.rng.uniform(), b = s.rng.uniform(), c = s.rng.uniform();
    return Color(a, c, b);
  };
  const auto by_dimension = [](const gi::Ray&, gi::PixelSample& s) {
    const double a = s.get_1d(17);
    const vec2 u = s.get_2d(4);
    return Color(a, u.x, u.y);
  };
  gi::Film one = gi::make_film(40, 35, 3), other = gi::make_film(40, 35, 3);
  gi::render_pass(one, camera, {gi::Sampler::Random, 2}, by_stream, 2);
  gi::render_pass(other, camera, {gi::Sampler::Random, 2}, by_dimension, 3);
  EXPECT_EQ(one.sum, other.sum);
  EXPECT_EQ(one.m2, other.m2);
}

// The other sequences are the sample stream of (pixel, sample, dimension), on any thread
// count, and their Random points are the sequence's pixel dimension.
TEST(RenderPass, StratifiedAndSobolReadTheSampleStream) {
  for (const gi::SamplerKind kind : {gi::SamplerKind::Stratified, gi::SamplerKind::Sobol}) {
    gi::Film film = gi::make_film(40, 35, 5, kind, 4);
    int wrong = 0;
    const auto check_numbers = [&](const gi::Ray&, gi::PixelSample& s) {
      const gi::SampleStream stream(film.sequence, s.pixel, static_cast<std::uint32_t>(s.index));
      const vec2 p = stream.get_2d(gi::pixel_dimension);
      wrong += s.get_1d(9) != stream.get_1d(9) || s.get_2d(3) != stream.get_2d(3) ||
               s.position != vec2(s.x + p.x, s.y + p.y);
      return Color(s.get_1d(2));
    };
    gi::render_pass(film, camera, {gi::Sampler::Random, 2}, check_numbers, 1);
    EXPECT_EQ(wrong, 0) << gi::sequence_name(kind);
    gi::Film again = gi::make_film(40, 35, 5, kind, 4);
    gi::render_pass(again, camera, {gi::Sampler::Random, 2}, [](const gi::Ray&, gi::PixelSample& s) {
      return Color(s.get_1d(2));
    }, 3);
    EXPECT_EQ(again.sum, film.sum) << gi::sequence_name(kind) << ": 1 and 3 threads";
  }
  EXPECT_EQ(gi::sequence_from_name("sobol"), gi::SamplerKind::Sobol);
  EXPECT_THROW(gi::sequence_from_name("halton"), std::invalid_argument);
}

TEST(RenderPass, SumsAndClampsOfRadianceFunctions) {
  const auto one = [](const gi::Ray&, gi::PixelSample&) { return Color(1.0, 2.0, 3.0); };
  const auto two = [](const gi::Ray&, gi::PixelSample&) { return Color(0.5); };
  gi::Film film = gi::make_film(2, 2, 1);
  gi::render_pass(film, camera, {}, gi::clamped(gi::sum_of(one, two), 2.0), 1);
  EXPECT_EQ(gi::film_mean(film).pixels[3], gi::Pixel(1.5f, 2.0f, 2.0f));
}

TEST(RenderPass, BadSamplingIsRefused) {
  gi::Film film = gi::make_film(2, 2, 1);
  EXPECT_THROW(gi::render_pass(film, camera, {gi::Sampler::Grid, 0}, linear, 1), std::invalid_argument);
  EXPECT_EQ(film.samples, 0);
  EXPECT_EQ(gi::samples_per_pass({gi::Sampler::Jittered, 3}), 9);
  EXPECT_EQ(gi::samples_per_pass({gi::Sampler::Adaptive, 4}), 1);
  EXPECT_EQ(gi::describe_pixel_samples({gi::Sampler::Jittered, 4}), "4 x 4 jittered eye rays, box filter");
}
