#include "gi/raytrace/render.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

namespace {

constexpr int tile_size = 32;

// What a tile's pixels share: the scene, the settings, the camera, the image, the
// tile's ray counts and its random stream (re-seeded for every pixel).
struct TileWork {
  const World& world;
  const RenderSettings& settings;
  const CameraFrame& frame;
  RenderResult& result;
  RayCounts& counts;
  Rng& rng;
};

// Pixels x0 .. x1 - 1 of row y, as sample_pixel samples them.
void render_row(TileWork& w, int y, int x0, int x1) {
  const std::function<Color(double, double)> radiance = [&](double px, double py) {
    w.counts.count(RayKind::Primary, 0);
    return trace(w.world, primary_ray(w.frame, px, py), w.settings.trace, w.counts, w.rng);
  };
  for (int x = x0; x < x1; ++x) {
    const std::size_t pixel = static_cast<std::size_t>(y) * w.settings.width + x;
    w.rng = Rng(w.settings.seed, pixel);
    w.result.image.pixels[pixel] =
        Pixel(sample_pixel(w.settings.sampling, x, y, w.rng, radiance, w.result.samples[pixel]));
  }
}

// The same for one eye ray through each pixel's centre (Sampler::Centre, the default):
// the same rays, traced in the same order, so the same bytes as render_row (a test
// compares the two). Each eye ray is made one pixel ahead: normalising its direction
// is a square root and a division in a chain, about 30 cycles, and made just before
// its trace it held up the start of every pixel (perf: 3% of the s10 render).
void render_row_of_centres(TileWork& w, int y, int x0, int x1) {
  const double py = y + 0.5;
  Ray eye = primary_ray(w.frame, x0 + 0.5, py);
  for (int x = x0; x < x1; ++x) {
    const Ray next = primary_ray(w.frame, (x + 1) + 0.5, py);  // past the row's end: made, not used
    const std::size_t pixel = static_cast<std::size_t>(y) * w.settings.width + x;
    w.rng = Rng(w.settings.seed, pixel);
    w.counts.count(RayKind::Primary, 0);
    w.result.image.pixels[pixel] = Pixel(trace(w.world, eye, w.settings.trace, w.counts, w.rng));
    w.result.samples[pixel] = 1;
    eye = next;
  }
}

}  // namespace

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
    Rng rng;  // re-seeded for every pixel
    TileWork work{world, settings, frame, result, tile_counts[tile], rng};
    const int x0 = (tile % tiles_x) * tile_size, x1 = std::min(x0 + tile_size, settings.width);
    const int y0 = (tile / tiles_x) * tile_size, y1 = std::min(y0 + tile_size, settings.height);
    for (int y = y0; y < y1; ++y) {
      if (settings.sampling.sampler == Sampler::Centre)
        render_row_of_centres(work, y, x0, x1);
      else
        render_row(work, y, x0, x1);
    }
  });
  result.seconds = timer.seconds();
  for (const RayCounts& counts : tile_counts) result.counts += counts;
  return result;
}

}  // namespace gi
