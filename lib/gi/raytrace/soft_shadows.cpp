#include "gi/raytrace/soft_shadows.hpp"

#include <stdexcept>

#include "gi/core/not_implemented.hpp"
#include "gi/render/pixel_samplers.hpp"

namespace gi {

namespace {
const char* const names[] = {"centre", "random", "jittered"};
}

std::string light_sampling_name(LightSampling sampling) { return names[static_cast<int>(sampling)]; }

std::vector<std::string> light_sampling_names() { return {std::begin(names), std::end(names)}; }

LightSampling light_sampling_from_name(const std::string& name) {
  for (int i = 0; i < 3; ++i)
    if (name == names[i]) return static_cast<LightSampling>(i);
  throw std::invalid_argument("unknown light sampling '" + name + "' (centre, random, jittered)");
}

void check(const SoftShadowSettings& settings) {
  if (settings.n < 1 || settings.n > 64) throw std::invalid_argument("soft shadows: n must lie in [1, 64]");
}

vec3 point_on_light(const QuadLight& light, vec2 uv) {
  // BEGIN EXERCISE 4.1 uniform point on a quad light
  return light.shape.corner + uv.x * light.shape.edge_u + uv.y * light.shape.edge_v;
  // END EXERCISE 4.1
}

// The same patterns that place eye rays in a pixel (lesson 03), here over the light.
std::vector<vec2> light_samples(const SoftShadowSettings& settings, Rng& rng) {
  switch (settings.sampling) {
    case LightSampling::Centre: return {vec2(0.5, 0.5)};
    case LightSampling::Random: {
      std::vector<vec2> uv;
      random_positions(settings.n * settings.n, rng, uv);
      return uv;
    }
    case LightSampling::Jittered: return jittered_positions(settings.n, rng);
  }
  return {};
}

Color soft_shadow_estimate(const QuadLight& light, const std::vector<vec2>& uv,
                           const std::function<bool(const vec3& y)>& visible,
                           const std::function<Color(const vec3& y)>& unshadowed) {
  // BEGIN EXERCISE 4.2 the soft-shadow estimate
  Color sum(0.0);
  for (const vec2& sample : uv) {
    const vec3 y = point_on_light(light, sample);
    if (visible(y)) sum += unshadowed(y);
  }
  return sum / static_cast<double>(uv.size());
  // END EXERCISE 4.2
}

}  // namespace gi
