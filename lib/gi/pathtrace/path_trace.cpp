#include "gi/pathtrace/path_trace.hpp"

#include <stdexcept>

#include "gi/render/render_pass.hpp"

namespace gi {

void path_trace(Film& film, const PathScene& scene, const PathSettings& settings, int spp, int threads) {
  check(settings);
  if (spp < 0) throw std::invalid_argument("path tracer: samples per pixel must be >= 0");
  const auto path = [&](const Ray& eye, PixelSample& sample) { return path_radiance(scene, eye, settings, sample); };
  for (int k = 0; k < spp; ++k) render_pass(film, scene.scene().camera, {Sampler::Random, 1}, path, threads);
}

}  // namespace gi
