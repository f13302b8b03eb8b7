#pragma once
#include "gi/image/image.hpp"
#include "gi/raytrace/ray_counts.hpp"
#include "gi/raytrace/whitted.hpp"
#include "gi/scene/scene.hpp"

namespace gi {

struct RenderSettings {
  int width = 640;
  int height = 480;
  int threads = 0;  // 0: all cores
  TraceSettings trace;
};

struct RenderResult {
  Image image;
  RayCounts counts;
  double seconds = 0;  // wall-clock time of the render loop alone
};

// Throws std::invalid_argument for settings out of range (size, depth, epsilon).
void check(const RenderSettings& settings);

// One eye ray through the centre of every pixel, traced recursively. The image
// is cut into 32x32 tiles that threads take in turn; every pixel depends only on
// the scene and the settings, so the image is the same for any thread count.
RenderResult render(const Scene& scene, const RenderSettings& settings);

}  // namespace gi
