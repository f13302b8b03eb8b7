#include "gi/render/render_pass.hpp"

#include <algorithm>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/render/adaptive.hpp"
#include "gi/render/pattern_numbers.hpp"

namespace gi {

namespace {

constexpr int tile_size = 32;

// An upper bound on an adaptive pixel's eye rays: the corners of a (2^L + 1)^2 grid.
long long adaptive_rays_at_most(int levels) {
  const long long side = (1LL << levels) + 1;
  return side * side;
}

}  // namespace

double PixelSample::get_1d(std::uint32_t dimension) {
  if (sequence.kind == SamplerKind::Independent) return rng.uniform();
  return SampleStream(sequence, pixel, static_cast<std::uint32_t>(index)).get_1d(dimension);
}

vec2 PixelSample::get_2d(std::uint32_t dimension) {
  if (sequence.kind == SamplerKind::Independent) {
    const double v = rng.uniform();  // the second coordinate first (render_pass.hpp)
    const double u = rng.uniform();
    return {u, v};
  }
  return SampleStream(sequence, pixel, static_cast<std::uint32_t>(index)).get_2d(dimension);
}

PixelSample stream_sample(Rng& rng) {
  static const SampleSequence independent{};
  return {0, 0, {}, 0, rng, independent, 0};
}

int samples_per_pass(const Sampling& s) {
  return s.sampler == Sampler::Centre || s.sampler == Sampler::Adaptive ? 1 : s.n * s.n;
}

int render_tasks(const Film& film) {
  return ((film.width + tile_size - 1) / tile_size) * ((film.height + tile_size - 1) / tile_size);
}

void render_pass(Film& film, const Camera& camera, const Sampling& sampling, RadianceFunction radiance, int threads) {
  check(sampling);
  const CameraFrame frame = camera_frame(camera, film.width, film.height);
  const int tiles_x = (film.width + tile_size - 1) / tile_size;
  // Centre and Grid draw nothing: one pattern serves every pixel.
  const std::vector<vec2> fixed = grid_positions(sampling.sampler == Sampler::Grid ? sampling.n : 1);
  const long long first = film.samples, added = samples_per_pass(sampling);
  const long long first_index =
      sampling.sampler == Sampler::Adaptive ? first * adaptive_rays_at_most(sampling.max_subdivisions) : first;
  std::vector<long long> discarded(render_tasks(film), 0);
  parallel_for(render_tasks(film), threads, [&](int tile) {
    std::vector<vec2> drawn;
    const int x0 = (tile % tiles_x) * tile_size, x1 = std::min(x0 + tile_size, film.width);
    const int y0 = (tile / tiles_x) * tile_size, y1 = std::min(y0 + tile_size, film.height);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * film.width + x;
        PixelSample sample{x, y, {}, first_index, film.rng[i], film.sequence, i};
        // L along the eye ray through point p of the pixel's unit square.
        const auto estimate = [&](vec2 p) {
          sample.position = vec2(x + p.x, y + p.y);
          const Color L = radiance(primary_ray(frame, sample.position.x, sample.position.y), sample);
          ++sample.index;
          return L;
        };
        const auto add = [&](long long n, const Color& L) {
          if (!add_sample(film, i, n, L)) ++discarded[tile];
        };
        if (sampling.sampler == Sampler::Adaptive) {
          add(first + 1, adaptive_sample(estimate, sampling.threshold, sampling.max_subdivisions).colour);
          continue;
        }
        const std::vector<vec2>* positions = &fixed;
        if (sampling.sampler == Sampler::Random || sampling.sampler == Sampler::Jittered) {
          pattern_points(sampling, sample, drawn);  // drawn whole, then its rays traced
          positions = &drawn;
        }
        long long n = first;
        for (const vec2& p : *positions) add(++n, estimate(p));
      }
  });
  film.samples += added;
  for (long long d : discarded) film.discarded += d;
}

}  // namespace gi
