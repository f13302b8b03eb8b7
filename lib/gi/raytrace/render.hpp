#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/image/image.hpp"
#include "gi/raytrace/ray_counts.hpp"
#include "gi/raytrace/whitted.hpp"
#include "gi/render/film.hpp"
#include "gi/render/pixel_samplers.hpp"

namespace gi {

struct RenderSettings {
  int width = 640;
  int height = 480;
  TraceSettings trace;
  Sampling sampling;  // eye rays per pixel (lesson 03); one through the centre by default
};

struct RenderResult {
  Image image;               // the film's mean: the picture
  RayCounts counts;
  std::vector<int> samples;  // eye rays per pixel, row-major
  double seconds = 0;        // wall-clock time of the render loop alone
};

// Throws std::invalid_argument for settings out of range (size, depth, epsilon).
void check(const RenderSettings& settings);

// Whitted's tracer as a radiance function (render_pass.hpp): eye rays through every
// pixel as the sampling says, each traced recursively by trace(), on `threads` threads
// (0 = all cores), added to `film` (of the settings' size) as one pass. Pixel i draws its
// sample positions and shadow rays from the film's stream i, so the image is the same for
// any thread count; the film keeps each pixel's spread (film_standard_error).
RenderResult render(const World& world, const RenderSettings& settings, Film& film, int threads);
// The same on a film of its own, whose streams are those of `seed`.
RenderResult render(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads);

}  // namespace gi
