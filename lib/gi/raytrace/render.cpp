#include "gi/raytrace/render.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

namespace {
constexpr int tile_size = 32;
}

std::string describe_pixel_samples(const Sampling& s) {
  const std::string grid = std::to_string(s.n) + " x " + std::to_string(s.n) + " ";
  switch (s.sampler) {
    case Sampler::Centre: return "one eye ray through the pixel centre";
    case Sampler::Grid: return grid + "eye rays on a regular grid, box filter";
    case Sampler::Random: return grid + "uniformly random eye rays, box filter";
    case Sampler::Jittered: return grid + "jittered eye rays, box filter";
    case Sampler::Adaptive:
    {
      char threshold[32];
      std::snprintf(threshold, sizeof threshold, "%g", s.threshold);
      return "adaptive (Whitted): pixel corners, subdivided up to " + std::to_string(s.max_subdivisions) +
             " times where they differ by more than " + threshold + ", box filter";
    }
  }
  return "?";
}

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

RenderResult render(const World& world, const RenderSettings& settings) {
  check(settings);
  const CameraFrame frame = camera_frame(world.scene.camera, settings.width, settings.height);
  const int tiles_x = (settings.width + tile_size - 1) / tile_size;
  const int tiles_y = (settings.height + tile_size - 1) / tile_size;

  RenderResult result{Image(settings.width, settings.height), {}, {}, 0};
  result.samples.assign(result.image.pixels.size(), 0);
  std::vector<RayCounts> tile_counts(static_cast<std::size_t>(tiles_x) * tiles_y);
  const Timer timer;
  parallel_for(tiles_x * tiles_y, settings.threads, [&](int tile) {
    RayCounts& counts = tile_counts[tile];
    Rng rng;  // re-seeded for every pixel below
    const int x0 = (tile % tiles_x) * tile_size;
    const int y0 = (tile / tiles_x) * tile_size;
    const std::function<Color(double, double)> radiance = [&](double px, double py) {
      counts.count(RayKind::Primary, 0);
      return trace(world, primary_ray(frame, px, py), settings.trace, counts, rng);
    };
    for (int y = y0; y < std::min(y0 + tile_size, settings.height); ++y) {
      for (int x = x0; x < std::min(x0 + tile_size, settings.width); ++x) {
        const std::size_t pixel = static_cast<std::size_t>(y) * settings.width + x;
        rng = Rng(settings.seed, pixel);
        result.image.pixels[pixel] = Pixel(sample_pixel(settings.sampling, x, y, rng, radiance, result.samples[pixel]));
      }
    }
  });
  result.seconds = timer.seconds();
  for (const RayCounts& counts : tile_counts) result.counts += counts;
  return result;
}

}  // namespace gi
