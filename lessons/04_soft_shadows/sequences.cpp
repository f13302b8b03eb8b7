// Lesson 04, step 3: the number sequences, error in the penumbra against shadow rays
// (sequences.hpp).
//
// A hit's n x n shadow rays are one set of N = n^2 numbers of the film's sequence
// (gi/raytrace/light_sample_numbers.hpp). Across the penumbra the visible part of the
// light is a step over the light's square: 1 on one side of the edge's image, 0 on the
// other. Independent points leave the Monte Carlo error,
//   RMS error ~ N^-1/2;
// stratified points leave variance only in the O(n) cells the step crosses,
//   Var = O(n) / N^2 = O(N^-3/2),  RMS error ~ N^-3/4,
// the law of jittered shadow rays in step 2; Sobol' points are a (0,m,2)-net when
// N = 2^m, every elementary box of area 1/N holding one point, and on a straight edge
// they do as well as the strata or a little better.
#include "sequences.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <vector>

#include "gi/render/sampler_study.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/table.hpp"

namespace lesson04 {
namespace {

constexpr gi::SamplerKind kinds[] = {gi::SamplerKind::Independent, gi::SamplerKind::Stratified,
                                     gi::SamplerKind::Sobol};
constexpr int sides[] = {1, 2, 4, 8};  // n: N = n^2 shadow rays per hit

double grey(const gi::Pixel& p) { return (double(p.x) + p.y + p.z) / 3; }

// The penumbra: pixels where the soft shadow differs from the hard one by more than 5%
// of the brighter. Lit and umbra pixels differ by the Phong term's spread over the light
// alone, well under that.
std::vector<std::size_t> penumbra_pixels(const gi::Image& reference, const gi::Image& hard) {
  std::vector<std::size_t> pixels;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const double r = grey(reference.pixels[i]), h = grey(hard.pixels[i]);
    if (std::abs(r - h) > 0.05 * std::max(r, h)) pixels.push_back(i);
  }
  return pixels;
}

// The RMS error over the penumbra, and its standard error by the delta method:
//   RMS = sqrt(mean d^2),  se(RMS) = se(mean d^2) / (2 RMS).
gi::LogLogPoint penumbra_rms(const gi::Image& test, const gi::Image& reference, const std::vector<std::size_t>& where,
                             int rays) {
  const double n = double(where.size());
  double mean = 0, m2 = 0;
  std::vector<double> squares;
  for (std::size_t i : where) {
    const double d = grey(test.pixels[i]) - grey(reference.pixels[i]);
    squares.push_back(d * d);
    mean += d * d / n;
  }
  for (double x : squares) m2 += (x - mean) * (x - mean);
  const double rms = std::sqrt(mean);
  return {double(rays), rms, rms > 0 ? std::sqrt(m2 / (n - 1) / n) / (2 * rms) : 0};
}

}  // namespace

void sequences(const gi::World& world, gi::RenderSettings settings, const gi::Image& reference, gi::Lesson& lesson) {
  settings.trace.soft_shadows = {gi::LightSampling::Centre, 1};
  const gi::Image hard = gi::render(world, settings, lesson.seed(), lesson.threads()).image;
  const std::vector<std::size_t> penumbra = penumbra_pixels(reference, hard);
  if (penumbra.size() < 2) {
    lesson.say("\nNo penumbra in this picture: the number sequences are not compared.\n");
    return;
  }

  std::vector<std::vector<gi::LogLogPoint>> errors(std::size(kinds));
  for (std::size_t k = 0; k < std::size(kinds); ++k)
    for (const int n : sides) {
      settings.trace.soft_shadows = {gi::LightSampling::Random, n};
      gi::Film film = gi::make_film(settings.width, settings.height, lesson.seed(), kinds[k]);
      const gi::Image picture = gi::render(world, settings, film, lesson.threads()).image;
      errors[k].push_back(penumbra_rms(picture, reference, penumbra, n * n));
    }

  std::vector<gi::Column> columns{{"rays/hit"}};
  for (const gi::SamplerKind kind : kinds) columns.push_back({gi::sequence_name(kind), 2, gi::Format::Scientific});
  gi::Table table("Random shadow rays read from three number sequences: RMS error over the penumbra (" +
                      std::to_string(penumbra.size()) + " pixels) against the reference",
                  columns);
  for (std::size_t j = 0; j < std::size(sides); ++j) {
    std::vector<gi::Cell> row{sides[j] * sides[j]};
    for (std::size_t k = 0; k < std::size(kinds); ++k) row.push_back(errors[k][j].error);
    table.add_row(row);
  }
  std::cout << '\n';
  lesson.table(table, "sequences");

  // The slope of log error against log N, and its standard error from each point's.
  gi::Table slopes("Fitted slope of log error against log rays per hit (Monte Carlo: -1/2, strata: -3/4)",
                   {{"sequence"}, {"slope", 2, gi::Format::Fixed}, {"+-", 2, gi::Format::Fixed}});
  std::vector<gi::Series> curves;
  for (std::size_t k = 0; k < std::size(kinds); ++k) {
    const gi::Slope fit = gi::fit_log_log_slope(errors[k]);
    slopes.add_row({gi::sequence_name(kinds[k]), fit.slope, fit.standard_error});
    gi::Series curve{gi::sequence_name(kinds[k]), {}, {}};
    for (const gi::LogLogPoint& p : errors[k]) curve.x.push_back(p.samples), curve.y.push_back(p.error);
    curves.push_back(curve);
  }
  lesson.table(slopes, "sequence_slopes");
  lesson.chart({"The penumbra's error against shadow rays per hit, by number sequence", "shadow rays per hit",
                "RMS error over the penumbra", true, true, curves},
               "sequences");
}

}  // namespace lesson04
