#include "gi/raytrace/light_sample_numbers.hpp"

namespace gi {

std::vector<vec2> light_samples(const SoftShadowSettings& settings, PixelSample& sample, std::uint32_t dimension) {
  if (settings.sampling == LightSampling::Centre || sample.sequence.kind == SamplerKind::Independent)
    return light_samples(settings, sample.rng);
  const int n = settings.n;
  const std::uint32_t count = static_cast<std::uint32_t>(n * n);
  // The hit's N numbers are set `sample.index` of a sequence whose sets are N long.
  const SampleSequence shadow_set = make_sample_sequence(sample.sequence.kind, sample.sequence.seed, count);
  const std::uint32_t first = static_cast<std::uint32_t>(sample.index) * count;
  std::vector<vec2> uv;
  uv.reserve(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    const vec2 p = SampleStream(shadow_set, sample.pixel, first + k).get_2d(dimension);
    // Jittered: cell (i, j) = (k mod n, k / n) of the n x n grid, offset p within it.
    if (settings.sampling == LightSampling::Jittered) uv.emplace_back((k % n + p.x) / n, (k / n + p.y) / n);
    else uv.push_back(p);
  }
  return uv;
}

}  // namespace gi
