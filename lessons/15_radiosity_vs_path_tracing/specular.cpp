// Lesson 15, step 3: the mirror-and-glass box (specular.hpp).
#include "specular.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"
#include "crops.hpp"

namespace lesson15 {

// 3. What radiosity cannot draw: the box with a mirror ball and a glass ball. Path
// tracing draws it, slowly where light comes by L S+ D paths: the caustic under the
// glass ball. Each region's noise is its pixels' mean relative standard error, from
// the film's own variance (no reference needed).
void specular(const Settings& s, gi::Lesson& lesson) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell-spheres"));
  gi::Film film = gi::make_film(s.size, s.size, s.seed);
  gi::Progress progress("mirror and glass", s.caustic_spp);
  std::vector<gi::Image> pictures;
  gi::Table table("The box with a mirror ball and a glass ball, path traced: noise where the light comes by a "
                  "caustic against a wall lit directly",
                  {{"spp"}, {"time s", 2}, {"caustic: rel. std. error %", 1}, {"back wall: rel. std. error %", 1},
                   {"ratio"}});
  const gi::Timer timer;
  for (int spp = s.caustic_spp / 16; spp <= s.caustic_spp; spp *= 4) {
    const int more = spp - static_cast<int>(film.samples);
    gi::path_trace(film, scene, {}, more, s.threads);
    progress.advance(more);
    const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
    // Mean relative standard error over a square of pixels (fractions of the picture).
    const auto noise = [&](double fx, double fy, double fw) {
      const int x0 = static_cast<int>(fx * s.size), y0 = static_cast<int>(fy * s.size), w = static_cast<int>(fw * s.size);
      double sum = 0;
      for (int y = y0; y < y0 + w; ++y)
        for (int x = x0; x < x0 + w; ++x) {
          const gi::Pixel m = mean.at(x, y), v = variance.at(x, y);
          sum += std::sqrt((v.x + v.y + v.z) / 3) / std::max(1e-6, (m.x + m.y + m.z) / 3.0);
        }
      return sum / (w * w);
    };
    const double caustic = noise(0.62, 0.88, 0.08), wall = noise(0.46, 0.20, 0.08);
    table.add_row({spp, timer.seconds(), 100 * caustic, 100 * wall, caustic / wall});
    pictures.push_back(mean);
  }
  progress.finish();
  lesson.table(table, "caustic_noise");
  lesson.say("to be as clean as the wall, the caustic needs (ratio)^2 times the samples: noise falls as 1/sqrt(spp)");
  const gi::View view{scene.scene().camera, s.size, s.size,
                      std::to_string(s.caustic_spp) + " paths per pixel through uniform random points of it (box filter)"};
  lesson.picture(pictures.back(), "mirror_and_glass", "cornell-spheres, path traced, " + std::to_string(s.caustic_spp) +
                                                          " spp: the mirror and the caustic radiosity cannot draw",
                 view, 1);
  std::vector<const gi::Image*> strip;
  for (const gi::Image& p : pictures) strip.push_back(&p);
  crops(strip, 0.5, 0.6, 0.38, "crop_caustic",
        "the floor under the glass ball at " + std::to_string(s.caustic_spp / 16) + ", " +
            std::to_string(s.caustic_spp / 4) + " and " + std::to_string(s.caustic_spp) + " spp",
        lesson);
}

}  // namespace lesson15
