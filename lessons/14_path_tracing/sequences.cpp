// Lesson 14, step 6: the number sequences, error against samples (sequences.hpp).
//
// A path's decisions each read a fixed dimension of the pixel's numbers
// (path_dimension). Independent numbers leave the error at the Monte Carlo rate,
//   RMS error ~ C N^-1/2,
// whatever the integrand. Stratified and Sobol' numbers spread each dimension evenly
// over the pixel's N samples, so where the pixel's integrand is smooth in the
// dimensions that carry its noise, the error falls faster -- up to N^-1 and N^-3/2 for
// a smooth integral (gi/render/sampler_study.hpp). On the box that is the direct
// light on the bright walls: the point on the light and the first BSDF direction. The
// two measures below weigh the pixels differently. Over the picture's mean, each pixel
// counts by its brightness, and the well-spread sequences pull ahead. Per pixel, the
// faces lit only by light that has bounced count as much as the bright ones; their
// noise is in the deeper bounces, whose decisions are spread one dimension at a time
// but not jointly, and there every sequence stays near N^-1/2.
#include "sequences.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_trace.hpp"
#include "gi/render/sampler_study.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/table.hpp"

namespace lesson14 {
namespace {

constexpr gi::SamplerKind kinds[] = {gi::SamplerKind::Independent, gi::SamplerKind::Stratified,
                                     gi::SamplerKind::Sobol};

double grey(const gi::Pixel& p) { return (double(p.x) + p.y + p.z) / 3; }

// An RMS with its standard error, from the squares it is the root of:
//   RMS = sqrt(mean x),  se(RMS) = se(mean x) / (2 RMS)  (the delta method).
gi::LogLogPoint rms_of(const std::vector<double>& squares, double samples) {
  const double n = double(squares.size());
  double mean = 0, m2 = 0;
  for (double x : squares) mean += x / n;
  for (double x : squares) m2 += (x - mean) * (x - mean);
  const double rms = std::sqrt(mean);
  return {samples, rms, std::sqrt(m2 / (n - 1) / n) / (2 * rms)};
}

// A picture's error against the reference, by two measures (grey, per pixel i):
//   per pixel    e_i = (t_i - r_i) / r_i, leaving out pixels whose reference is below
//                1e-3 of the mean: every pixel counts alike, the dark ones most
//   over mean    d_i = (t_i - r_i) / mean r: each pixel by its brightness, the bright
//                ones most
struct PictureError {
  gi::LogLogPoint per_pixel, over_mean;
  std::vector<double> relative;  // |e_i| per pixel, 0 where left out
};
PictureError picture_error(const gi::Image& test, const gi::Image& reference, int spp) {
  double mean_reference = 0;
  for (const gi::Pixel& r : reference.pixels) mean_reference += grey(r) / double(reference.pixels.size());
  PictureError out;
  std::vector<double> per_pixel, over_mean;
  for (std::size_t i = 0; i < test.pixels.size(); ++i) {
    const double r = grey(reference.pixels[i]), d = grey(test.pixels[i]) - r;
    over_mean.push_back(d * d / (mean_reference * mean_reference));
    out.relative.push_back(0);
    if (r < 1e-3 * mean_reference) continue;
    out.relative.back() = std::abs(d / r);
    per_pixel.push_back(d * d / (r * r));
  }
  out.per_pixel = rms_of(per_pixel, spp);
  out.over_mean = rms_of(over_mean, spp);
  return out;
}

}  // namespace

SequenceSettings sequence_settings(int width, int height, int max_spp) {
  SequenceSettings s;
  while (s.side > std::min(width, height)) s.side /= 2;
  s.max_spp = std::clamp(max_spp, 2, 64);
  return s;
}

void sequences(const SequenceSettings& s, const gi::Truth& reference, gi::Lesson& lesson) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  std::vector<int> counts;
  for (int n = 1; n <= s.max_spp; n *= 2) counts.push_back(n);

  // Each N its own picture, from its own first sample: a stratified sequence needs its
  // N before the first sample, and the points of the fit stay independent of each other.
  std::vector<std::vector<PictureError>> errors(std::size(kinds));
  for (std::size_t k = 0; k < std::size(kinds); ++k)
    for (const int n : counts) {
      gi::Film film = gi::make_film(s.side, s.side, s.seed, kinds[k], static_cast<std::uint32_t>(n));
      gi::path_trace(film, scene, {}, n, s.threads);
      errors[k].push_back(picture_error(gi::film_mean(film), reference.mean, n));
    }
  const auto measure = [&](std::size_t k, std::size_t j, bool per_pixel) {
    return per_pixel ? errors[k][j].per_pixel : errors[k][j].over_mean;
  };

  std::vector<gi::Column> columns{{"spp"}};
  for (const bool per_pixel : {true, false})
    for (const gi::SamplerKind kind : kinds)
      columns.push_back({(per_pixel ? "rel. " : "/mean ") + std::string(gi::sequence_name(kind)), 2,
                         gi::Format::Scientific});
  gi::Table table("Number sequences on the Cornell box, " + std::to_string(s.side) + "x" + std::to_string(s.side) +
                      " (MIS), a fresh picture at each spp: relative RMS error against the reference per pixel "
                      "(rel.) and RMS error over the picture's mean (/mean)",
                  columns);
  for (std::size_t j = 0; j < counts.size(); ++j) {
    std::vector<gi::Cell> row{counts[j]};
    for (const bool per_pixel : {true, false})
      for (std::size_t k = 0; k < std::size(kinds); ++k) row.push_back(measure(k, j, per_pixel).error);
    table.add_row(row);
  }
  std::cout << '\n';
  lesson.table(table, "sequences");

  // The slope of log error against log N, and its standard error from each point's.
  gi::Table slopes("Fitted slope of log error against log spp (Monte Carlo: -1/2)",
                   {{"sequence"},
                    {"rel. slope", 2, gi::Format::Fixed},
                    {"rel. +-", 2, gi::Format::Fixed},
                    {"/mean slope", 2, gi::Format::Fixed},
                    {"/mean +-", 2, gi::Format::Fixed}});
  std::vector<gi::Series> curves;
  for (std::size_t k = 0; k < std::size(kinds); ++k) {
    std::vector<gi::Cell> row{gi::sequence_name(kinds[k])};
    for (const bool per_pixel : {true, false}) {
      std::vector<gi::LogLogPoint> points;
      gi::Series curve{(per_pixel ? "rel. " : "/mean ") + std::string(gi::sequence_name(kinds[k])), {}, {},
                       per_pixel ? gi::Mark::LinePoints : gi::Mark::Points};
      for (std::size_t j = 0; j < counts.size(); ++j) {
        points.push_back(measure(k, j, per_pixel));
        curve.x.push_back(counts[j]), curve.y.push_back(points.back().error);
      }
      const gi::Slope fit = gi::fit_log_log_slope(points);
      row.push_back(fit.slope), row.push_back(fit.standard_error);
      curves.push_back(curve);
    }
    slopes.add_row(row);
  }
  lesson.table(slopes, "sequence_slopes");
  lesson.chart({"Cornell box, " + std::to_string(s.side) + "x" + std::to_string(s.side) +
                    ": error against samples per pixel, per pixel (lines) and over the mean (points)",
                "samples per pixel", "relative RMS error", true, true, curves},
               "sequences");

  // Where each sequence's error is, at the largest N: |t - r| / r per pixel.
  std::vector<gi::Image> maps;
  for (std::size_t k = 0; k < std::size(kinds); ++k)
    maps.push_back(gi::false_colour(errors[k].back().relative, s.side, s.side, 0, 0.5));
  lesson.diagram(gi::side_by_side(maps), "sequences_error",
                 "each pixel's relative error at " + std::to_string(counts.back()) +
                     " spp: independent, stratified, Sobol'; black 0 to red 50%",
                 gi::ColourScale{0, 0.5, "|t - r| / r of the pixel"});
}

}  // namespace lesson14
