// Lesson 14: one strategy, sample after sample (converge.hpp).
#include "converge.hpp"

#include <algorithm>
#include <cmath>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/metrics.hpp"
#include "gi/report/progress.hpp"

namespace lesson14 {
namespace {

// The picture's view, as its page describes it: spp paths per pixel, a box filter.
gi::View view(const gi::PathScene& scene, int width, int height, int spp,
              gi::SamplerKind sequence = gi::SamplerKind::Independent) {
  const std::string points = sequence == gi::SamplerKind::Independent
                                 ? "uniform random points of it"
                                 : std::string(gi::sequence_name(sequence)) + " points of it";
  return {scene.scene().camera, width, height, std::to_string(spp) + " paths per pixel through " + points + " (box filter)"};
}

}  // namespace

double grey(const gi::Pixel& p) { return (double(p.x) + p.y + p.z) / 3; }

double mean_of(const gi::Image& image) {
  double sum = 0;
  for (const gi::Pixel& p : image.pixels) sum += grey(p);
  return sum / double(image.pixels.size());
}

std::vector<Snapshot> converge(const gi::PathScene& scene, const Settings& s, gi::Strategy strategy,
                               const gi::Truth& reference, gi::Lesson* pictures) {
  gi::PathSettings path = s.path;
  path.strategy = strategy;
  // A stratified sequence is stratified over the last picture's spp.
  gi::Film film = gi::make_film(s.width, s.height, s.seed, s.sequence, static_cast<std::uint32_t>(s.max_spp));
  std::vector<Snapshot> snapshots;
  std::vector<gi::Image> strip;  // the pictures at 1, 4, 16, ... spp, then the reference
  gi::Progress progress(gi::name(strategy), s.max_spp);
  double seconds = 0;
  for (int spp = 1; spp <= s.max_spp; spp *= 2) {
    const gi::Timer timer;
    gi::path_trace(film, scene, path, spp - static_cast<int>(film.samples), s.threads);
    seconds += timer.seconds();
    progress.advance(spp / 2 + (spp == 1));
    const gi::Image picture = gi::film_mean(film);
    snapshots.push_back({spp, seconds, gi::rmse(picture, reference.mean),
                         gi::relative_rms_error(picture, reference.mean), mean_of(gi::film_variance(film))});
    const bool power_of_four = (spp & 0x55555555) != 0;
    if (pictures && power_of_four) {
      pictures->picture(picture, s.scene + "_" + std::to_string(spp) + "spp",
                        s.scene + ", " + gi::name(strategy) + ", " + std::to_string(spp) + " spp",
                        view(scene, s.width, s.height, spp, s.sequence));
      strip.push_back(picture);
    }
  }
  progress.finish();
  if (film.discarded && pictures)
    pictures->say(gi::name(strategy) + ": " + std::to_string(film.discarded) + " samples not finite, counted as 0");
  if (pictures) {
    // Where the noise is: each pixel's relative standard error, sqrt(variance) / mean.
    const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
    std::vector<double> relative;
    for (std::size_t i = 0; i < mean.pixels.size(); ++i)
      relative.push_back(std::sqrt(grey(variance.pixels[i])) / std::max(1e-6, grey(mean.pixels[i])));
    pictures->diagram(gi::false_colour(relative, s.width, s.height, 0, 0.5),
                      "relative_error_" + std::to_string(s.max_spp) + "spp",
                      "each pixel's relative standard error at the last picture, black 0 to red 50%",
                      gi::ColourScale{0, 0.5, "relative standard error of the pixel's mean"});
    strip.push_back(reference.mean);
    pictures->diagram(gi::side_by_side(strip), "progression", "1, 4, 16, ... spp, then the reference");
    pictures->picture(reference.mean, "reference", "the reference, " + std::to_string(reference.spp) + " spp",
                      view(scene, s.width, s.height, static_cast<int>(reference.spp)));
  }
  return snapshots;
}

}  // namespace lesson14
