#pragma once
#include "gi/core/ray.hpp"
#include "gi/pathtrace/mis.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/render/render_pass.hpp"

namespace gi {

// Kajiya's rendering equation, the radiance leaving x in direction wo:
//   L(x, wo) = L_e(x, wo) + int f(wo, wi) L(x'(x, wi), -wi) |cos theta_i| dw_i
// solved by Monte Carlo with one random path per sample: from the eye, at each
// surface add what the chosen strategy (mis.hpp) finds of the emitted light, then
// continue in one direction drawn from the BSDF. The path's throughput beta is the
// product of the BSDF weights f |cos| / p so far. Radiosity is the special case in
// which every f is rho / pi.
struct PathSettings {
  Strategy strategy = Strategy::Mis;
  int max_depth = 64;      // bounces: 0 shows only what emits, 1 adds direct light, 2 one bounce more ...
  int roulette_depth = 3;  // Russian roulette may end a path from this bounce on
};

// Throws std::invalid_argument for max_depth outside [0, 100000] or roulette_depth < 0.
void check(const PathSettings& settings);

// The radiance arriving at ray.origin along -ray.direction (unit), one path's estimate.
// Each decision reads its own dimension of the sample's numbers, path_dimension(bounce,
// decision) (sample_stream.hpp): with a stratified or Sobol' sequence, the light points of
// the first bounce are spread across the pixel's samples, and so are its BSDF directions.
Color path_radiance(const PathScene& scene, const Ray& ray, const PathSettings& settings, PixelSample& sample);

}  // namespace gi
