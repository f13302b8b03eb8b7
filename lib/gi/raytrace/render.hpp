#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/raytrace/pixel_samplers.hpp"
#include "gi/raytrace/ray_counts.hpp"
#include "gi/raytrace/whitted.hpp"
#include "gi/accel/world.hpp"

namespace gi {

struct RenderSettings {
  int width = 640;
  int height = 480;
  int threads = 0;  // 0: all cores
  TraceSettings trace;
  Sampling sampling;       // eye rays per pixel (lesson 03); one through the centre by default
  std::uint64_t seed = 1;  // random sample positions: pixel i draws from stream i of this seed
};

struct RenderResult {
  Image image;
  RayCounts counts;
  std::vector<int> samples;  // eye rays per pixel, row-major
  double seconds = 0;        // wall-clock time of the render loop alone
};

// How the eye rays sample each pixel, for a reader who wants the same picture:
// "one eye ray through the pixel centre", "4 x 4 jittered eye rays, box filter" ...
std::string describe_pixel_samples(const Sampling& sampling);

// Throws std::invalid_argument for settings out of range (size, depth, epsilon).
void check(const RenderSettings& settings);

// Eye rays through every pixel as the sampling says, traced recursively. The image
// is cut into 32x32 tiles that threads take in turn; every pixel depends only on
// the scene, the settings and its own random stream, so the image is the same for
// any thread count.
RenderResult render(const World& world, const RenderSettings& settings);

}  // namespace gi
