#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/core/rng.hpp"
#include "gi/scene/light.hpp"

namespace gi {

// How a shading point samples an area light with shadow rays:
//   Centre    one shadow ray to the light's centre: a point light there, hard shadows
//   Random    n*n uniform random points on the light
//   Jittered  one uniform point in each cell of an n x n grid over the light
enum class LightSampling { Centre, Random, Jittered };

struct SoftShadowSettings {
  LightSampling sampling = LightSampling::Jittered;
  int n = 3;  // n x n shadow rays per shading point and area light
};

std::string light_sampling_name(LightSampling sampling);
std::vector<std::string> light_sampling_names();
LightSampling light_sampling_from_name(const std::string& name);  // throws std::invalid_argument

// Throws std::invalid_argument for n outside [1, 64].
void check(const SoftShadowSettings& settings);

// The point of the light at (u, v) of its unit square: corner + u edge_u + v edge_v.
// Uniform (u, v) give points uniform over the parallelogram's area.
vec3 point_on_light(const QuadLight& light, vec2 uv);

// Where on the light (in its unit square) one shading point sends its shadow rays.
std::vector<vec2> light_samples(const SoftShadowSettings& settings, Rng& rng);

// The light a surface point x receives from an area light, soft shadows included:
// the mean over the sample points y_k = point_on_light(light, uv[k]) of
//   S(x, y_k) I(x, y_k),    k = 1..N,
// with S the visibility (1 when the shadow ray from x reaches y_k) and I what a
// point light at y_k would give x unshadowed. Points the shadow rays do not reach
// count as zero, so the mean is over all N samples.
Color soft_shadow_estimate(const QuadLight& light, const std::vector<vec2>& uv,
                           const std::function<bool(const vec3& y)>& visible,
                           const std::function<Color(const vec3& y)>& unshadowed);

}  // namespace gi
