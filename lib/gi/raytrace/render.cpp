#include "gi/raytrace/render.hpp"

#include <stdexcept>
#include <string>

#include "gi/core/per_thread.hpp"
#include "gi/core/timer.hpp"
#include "gi/render/render_pass.hpp"

namespace gi {

void check(const RenderSettings& s) {
  if (s.width <= 0 || s.height <= 0 || s.width > 16384 || s.height > 16384)
    throw std::invalid_argument("render: width and height must lie in [1, 16384]");
  if (s.trace.max_depth < 0 || s.trace.max_depth >= RayCounts::max_depth)
    throw std::invalid_argument("render: the depth limit must lie in [0, " + std::to_string(RayCounts::max_depth - 1) +
                                "]");
  if (!(s.trace.min_contribution >= 0 && s.trace.min_contribution <= 1))
    throw std::invalid_argument("render: the contribution threshold must lie in [0, 1]");
  if (!(s.trace.epsilon > 0 && s.trace.epsilon < 1))
    throw std::invalid_argument("render: epsilon must lie in (0, 1)");
  check(s.sampling);
  check(s.trace.soft_shadows);
}

RenderResult render(const World& world, const RenderSettings& settings, Film& film, int threads) {
  check(settings);
  if (film.width != settings.width || film.height != settings.height)
    throw std::invalid_argument("render: the film is not the settings' size");
  RenderResult result;
  result.samples.assign(static_cast<std::size_t>(settings.width) * settings.height, 0);
  PerThread<RayCounts> thread_counts;
  // L(ray) by Whitted's recursion, each eye ray counted (per thread: no lock) and
  // tallied for its pixel.
  const auto whitted = [&](const Ray& eye, PixelSample& sample) {
    ++result.samples[static_cast<std::size_t>(sample.y) * settings.width + sample.x];
    RayCounts& counts = thread_counts.mine();
    counts.count(RayKind::Primary, 0);
    return trace(world, eye, settings.trace, counts, sample);
  };
  const Timer timer;
  render_pass(film, world.scene.camera, settings.sampling, whitted, threads);
  result.seconds = timer.seconds();
  for (const RayCounts& counts : thread_counts.all()) result.counts += counts;
  result.image = film_mean(film);
  return result;
}

RenderResult render(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads) {
  check(settings);
  Film film = make_film(settings.width, settings.height, seed);
  return render(world, settings, film, threads);
}

}  // namespace gi
