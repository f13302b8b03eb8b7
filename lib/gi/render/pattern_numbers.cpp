#include "gi/render/pattern_numbers.hpp"

namespace gi {

void pattern_points(const Sampling& sampling, PixelSample& sample, std::vector<vec2>& points) {
  const int n = sampling.n;
  points.clear();
  if (sample.sequence.kind == SamplerKind::Independent) {
    if (sampling.sampler == Sampler::Random) random_positions(n * n, sample.rng, points);
    else points = jittered_positions(n, sample.rng);
    return;
  }
  const long long first = sample.index;
  for (int k = 0; k < n * n; ++k, ++sample.index) {
    const vec2 p = sample.get_2d(pixel_dimension);
    // Jittered: cell (i, j) = (k mod n, k / n) covers [i/n, (i+1)/n) x [j/n, (j+1)/n).
    if (sampling.sampler == Sampler::Jittered) points.emplace_back((k % n + p.x) / n, (k / n + p.y) / n);
    else points.push_back(p);
  }
  sample.index = first;
}

}  // namespace gi
