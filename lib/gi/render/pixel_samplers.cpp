#include "gi/render/pixel_samplers.hpp"

#include <cstdio>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

namespace {
const char* const names[] = {"centre", "grid", "random", "jittered", "adaptive"};
}

std::string sampler_name(Sampler sampler) { return names[static_cast<int>(sampler)]; }

std::vector<std::string> sampler_names() { return {std::begin(names), std::end(names)}; }

Sampler sampler_from_name(const std::string& name) {
  for (int i = 0; i < 5; ++i)
    if (name == names[i]) return static_cast<Sampler>(i);
  throw std::invalid_argument("unknown sampler '" + name + "' (centre, grid, random, jittered, adaptive)");
}

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

void check(const Sampling& s) {
  if (s.n < 1 || s.n > 64) throw std::invalid_argument("sampling: n must lie in [1, 64]");
  if (!(s.threshold >= 0)) throw std::invalid_argument("sampling: the adaptive threshold must be >= 0");
  if (s.max_subdivisions < 0 || s.max_subdivisions > 8)
    throw std::invalid_argument("sampling: adaptive subdivisions must lie in [0, 8]");
}

std::vector<vec2> grid_positions(int n) {
  std::vector<vec2> positions;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) positions.emplace_back((i + 0.5) / n, (j + 0.5) / n);
  return positions;
}

void random_positions(int count, Rng& rng, std::vector<vec2>& positions) {
  for (int k = 0; k < count; ++k) {
    const double u = rng.uniform();
    positions.emplace_back(u, rng.uniform());
  }
}

std::vector<vec2> jittered_positions(int n, Rng& rng) {
  // Cell (i, j) covers [i/n, (i+1)/n) x [j/n, (j+1)/n); one uniform point in each.
  // BEGIN EXERCISE 3.1 jittered sample positions
  std::vector<vec2> positions;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = rng.uniform();
      positions.emplace_back((i + u) / n, (j + rng.uniform()) / n);
    }
  return positions;
  // END EXERCISE 3.1
}

bool should_subdivide(const std::array<Color, 4>& corners, double threshold) {
  // BEGIN EXERCISE 3.2 adaptive subdivision decision
  const Color mean = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
  for (const Color& c : corners)
    if (max_component(glm::abs(c - mean)) > threshold) return true;
  return false;
  // END EXERCISE 3.2
}

}  // namespace gi
