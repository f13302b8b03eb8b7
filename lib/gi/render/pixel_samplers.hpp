#pragma once
#include <array>
#include <string>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/core/rng.hpp"

namespace gi {

// Where in a pixel the eye rays go, the lecture's cures for aliasing:
//   Centre    one ray through the pixel's centre (aliases)
//   Grid      direct supersampling on an n x n grid (regular: still aliases, higher up)
//   Random    n*n stochastic samples, uniform over the pixel (noise instead of aliasing)
//   Jittered  one random sample in each cell of an n x n grid (stratified: less noise)
//   Adaptive  Whitted's: sample the corners, subdivide where they differ
enum class Sampler { Centre, Grid, Random, Jittered, Adaptive };

struct Sampling {
  Sampler sampler = Sampler::Centre;
  int n = 1;                  // Grid, Random, Jittered: n x n samples per pixel
  double threshold = 0.1;     // Adaptive: subdivide when corners differ by more than this
  int max_subdivisions = 2;   // Adaptive: depth limit of the subdivision
};

std::string sampler_name(Sampler sampler);
std::vector<std::string> sampler_names();
Sampler sampler_from_name(const std::string& name);  // throws std::invalid_argument

// How the eye rays sample each pixel, for a reader who wants the same picture:
// "one eye ray through the pixel centre", "4 x 4 jittered eye rays, box filter" ...
std::string describe_pixel_samples(const Sampling& sampling);

// Sample positions in the unit square [0, 1)^2 of a pixel.
std::vector<vec2> grid_positions(int n);                                // cell centres of an n x n grid
void random_positions(int count, Rng& rng, std::vector<vec2>& positions);  // appends `count`, independent, uniform
std::vector<vec2> jittered_positions(int n, Rng& rng);                   // one uniform point per grid cell

// Whitted's test: do the radiances at a square's four corners differ by more than
// `threshold` (in any colour channel) from their mean?
bool should_subdivide(const std::array<Color, 4>& corners, double threshold);

// Throws std::invalid_argument for n outside [1, 64], a negative threshold or
// max_subdivisions outside [0, 8].
void check(const Sampling& sampling);

}  // namespace gi
