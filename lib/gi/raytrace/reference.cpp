#include "gi/raytrace/reference.hpp"

#include <cstdio>

#include "gi/core/hash.hpp"

namespace gi {

namespace {

std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// Everything that fixes the picture, the code aside: what names the files, so that a
// change of code replaces them instead of adding some.
std::vector<std::pair<std::string, std::string>> settings_of(const World& world, const RenderSettings& s,
                                                             std::uint64_t seed, const std::string& scene_key) {
  return {{"scene", scene_key},
          {"acceleration", name(world.acceleration)},
          {"max_depth", std::to_string(s.trace.max_depth)},
          {"min_contribution", exact(s.trace.min_contribution)},
          {"epsilon", exact(s.trace.epsilon)},
          {"shadow_sampling", light_sampling_name(s.trace.soft_shadows.sampling)},
          {"shadow_n", std::to_string(s.trace.soft_shadows.n)},
          {"sampler", sampler_name(s.sampling.sampler)},
          {"sampler_n", std::to_string(s.sampling.n)},
          {"threshold", exact(s.sampling.threshold)},
          {"max_subdivisions", std::to_string(s.sampling.max_subdivisions)},
          {"seed", std::to_string(seed)}};
}

std::string fingerprint_of(const std::vector<std::pair<std::string, std::string>>& settings, int width, int height) {
  std::string text = "width " + std::to_string(width) + "\nheight " + std::to_string(height) + '\n';
  for (const auto& [name, value] : settings) text += name + ' ' + value + '\n';
  return hex(fnv1a(text));
}

}  // namespace

TruthKey reference_key(const World& world, const RenderSettings& settings, std::uint64_t seed,
                       const std::string& scene_key) {
  return {fingerprint_of(settings_of(world, settings, seed, scene_key), settings.width, settings.height),
          render_code_fingerprint(), settings.width, settings.height};
}

CachedTruth cached_reference(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads,
                             const std::string& scene_key, const std::filesystem::path& folder) {
  const TruthKey key = reference_key(world, settings, seed, scene_key);
  return cached_truth(folder / ("reference_" + key.fingerprint), key, seed,
                      [&](const std::string&) {
                        Film film = make_film(settings.width, settings.height, seed);
                        render(world, settings, film, threads);
                        return film;
                      },
                      settings_of(world, settings, seed, scene_key));
}

}  // namespace gi
