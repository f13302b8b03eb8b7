#pragma once
#include <cstdint>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/image/image.hpp"
#include "gi/pathtrace/path_integrator.hpp"

namespace gi {

// A picture being path traced, sample by sample: per pixel its random stream, and the
// running mean and spread of its samples (Welford's update, exact in any order of
// passes):
//   n += 1,  delta = x - mean,  mean += delta / n,  m2 += delta (x - mean)
// so that the variance of the pixel's mean is s^2 / n = m2 / (n (n - 1)): each pixel's
// own error bar, measured from its samples. Passes of more samples continue every
// pixel's stream where the last pass left it, so 1 + 3 samples are the same as 4.
struct Film {
  int width = 0;
  int height = 0;
  long long samples = 0;    // per pixel, so far
  long long discarded = 0;  // samples that were not finite numbers: counted as 0, and reported
  std::vector<Rng> rng;     // pixel i draws from stream i of the seed
  std::vector<Color> mean;
  std::vector<Color> m2;
};

// Throws std::invalid_argument for a size outside [1, 16384].
Film make_film(int width, int height, std::uint64_t seed);

// Adds `spp` samples to every pixel: eye rays through uniform random points of the
// pixel (a box filter) by the scene's camera, each traced by path_radiance. Rows are
// shared among `threads` (0 = all cores); every pixel draws only from its own stream,
// so the film is the same for any number of threads.
void render_pass(Film& film, const PathScene& scene, const PathSettings& settings, int spp, int threads);

Image film_mean(const Film& film);      // radiance, linear
Image film_variance(const Film& film);  // variance of each pixel's mean, per channel (0 below 2 samples)

}  // namespace gi
