// Lesson 14: Veach's glossy plates (veach_plates.hpp).
#include "veach_plates.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/pathtrace/path_trace.hpp"
#include "gi/pathtrace/veach_plates.hpp"

namespace lesson14 {
namespace {

struct Rendered {
  gi::Image picture;
  double seconds;
};

Rendered render(const gi::PathScene& scene, int width, int height, gi::Strategy strategy, int spp,
                std::uint64_t seed, int threads) {
  gi::PathSettings path;
  path.strategy = strategy;
  gi::Film film = gi::make_film(width, height, seed);
  const gi::Timer timer;
  gi::path_trace(film, scene, path, spp, threads);
  return {gi::film_mean(film), timer.seconds()};
}

// The ramp of false_colour from lo to hi, as a strip as wide as `width`: the colour bar
// printed under the maps, so that the picture carries its scale off the report page too.
gi::Image colour_bar(int width, int height) {
  std::vector<double> ramp;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) ramp.push_back((x + 0.5) / width);
  return gi::false_colour(ramp, width, height, 0, 1);
}

}  // namespace

void veach_plates(const PlatesSettings& s, gi::Lesson& lesson) {
  const gi::PathScene scene = gi::make_path_scene(gi::veach_plates_scene());
  const int width = s.width * 3 / 2, height = std::max(1, s.width * 9 / 8);  // 4:3
  const std::uint64_t reference_seed = s.seed + 1000000;  // streams no picture measured uses
  const Rendered reference = render(scene, width, height, gi::Strategy::Mis, s.reference_spp, reference_seed, s.threads);

  // Scored on the plates (the lights seen directly are the same in every strategy), and
  // on the figure's two corners: the sharpest plate's smallest light and the roughest
  // plate's largest (highlight_mask).
  const double epsilon = scene.scene().background.x;  // the sky's radiance (grey)
  const std::vector<char> on_plates = gi::plates_mask(scene, width, height);
  const std::vector<char> sharp_small = gi::highlight_mask(scene, width, height, 0, 0);
  const std::vector<char> rough_large =
      gi::highlight_mask(scene, width, height, gi::plate_count - 1, gi::plate_light_count - 1);
  const auto score = [&](const std::vector<double>& errors, const std::vector<char>& mask) {
    return std::find(mask.begin(), mask.end(), 1) == mask.end() ? gi::Cell("-") : gi::Cell(gi::rms_over(errors, mask));
  };
  gi::Table table("Veach's plates, " + std::to_string(width) + "x" + std::to_string(height) +
                      ": relative RMS error against MIS at " + std::to_string(s.reference_spp) +
                      " spp, over the plates and where the sharpest plate shows the smallest light and "
                      "the roughest the largest",
                  {{"strategy"},
                   {"spp"},
                   {"time (s)", 3},
                   {"rel. RMS", 3, gi::Format::Fixed},
                   {"sharp, small", 3, gi::Format::Fixed},
                   {"rough, large", 3, gi::Format::Fixed}});
  std::vector<gi::Image> pictures, maps;
  for (const gi::Strategy strategy : {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis}) {
    const Rendered r = render(scene, width, height, strategy, s.spp, s.seed, s.threads);
    const std::vector<double> errors = gi::relative_error_map(r.picture, reference.picture, epsilon);
    table.add_row({gi::name(strategy), s.spp, r.seconds, gi::rms_over(errors, on_plates), score(errors, sharp_small),
                   score(errors, rough_large)});
    pictures.push_back(r.picture);
    std::vector<double> shown = errors;  // the map shows what is scored: the plates
    for (std::size_t i = 0; i < shown.size(); ++i)
      if (!on_plates[i]) shown[i] = 0;
    maps.push_back(gi::false_colour(shown, width, height, 0, 1));
  }
  std::cout << '\n';
  lesson.table(table, "plates");
  lesson.say("images: " + lesson.out().string() +
             "/ (plates.png: bsdf, lights, mis and the reference; plates_error.png: each pixel's error, black 0 to "
             "red 1)");
  pictures.push_back(reference.picture);
  lesson.diagram(gi::side_by_side(pictures), "plates",
                 "Veach's plates: BSDF sampling, light sampling, MIS at " + std::to_string(s.spp) +
                     " spp, and the reference (exposure 2)",
                 2.0);
  const gi::Image strip = gi::side_by_side(maps);
  lesson.diagram(gi::image_grid({strip, colour_bar(strip.width, std::max(2, height / 12))}, 1), "plates_error",
                 "each pixel's error |t - r| / (r + sky): BSDF sampling, light sampling, MIS",
                 gi::ColourScale{0, 1, "|t - r| / (r + the sky's radiance), grey, against the reference"});
}

}  // namespace lesson14
