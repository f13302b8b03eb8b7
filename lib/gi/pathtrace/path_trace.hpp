#pragma once
#include "gi/pathtrace/path_integrator.hpp"
#include "gi/render/film.hpp"

namespace gi {

// The path tracer at the pixel: adds `spp` samples to every pixel of `film`, each an eye
// ray through a uniform random point of the pixel (a box filter) by the scene's camera,
// traced by path_radiance -- render_pass's Random sampler, one sample a pass, so that
// every pixel's stream continues from pass to pass and 1 + 3 samples are the same as 4.
// The numbers are the film's sequence (make_film): independent, stratified or Sobol'.
// On `threads` threads (0 = all cores); the film is the same for any number.
// Throws std::invalid_argument for bad settings or a negative spp.
void path_trace(Film& film, const PathScene& scene, const PathSettings& settings, int spp, int threads);

}  // namespace gi
