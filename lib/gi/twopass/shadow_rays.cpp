#include "gi/twopass/shadow_rays.hpp"

#include <stdexcept>

#include "gi/radiosity/mesh/polygon.hpp"
#include "gi/raytrace/light_sample_numbers.hpp"

namespace gi {

ShadowRayLights shadow_ray_lights(const Mesh& mesh, int cells) {
  if (cells < 1 || cells > 64) throw std::invalid_argument("shadow rays: cells must lie in [1, 64]");
  ShadowRayLights lights{{}, cells};
  for (const Surface& s : mesh.surfaces)
    if (max_component(s.emission) > 0) lights.lights.push_back(s);
  return lights;
}

namespace {

// H(x), with points(l) the cells^2 points of light l in its (s, t) square, the k-th in
// stratum k. A light's points are drawn whole before its rays: tracing draws nothing.
template <class Points>
Color irradiance(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n, Points&& points) {
  Color H(0.0);
  const int m = lights.cells;
  for (std::size_t l = 0; l < lights.lights.size(); ++l) {
    const Surface& light = lights.lights[l];
    const auto& c = light.corners;
    const std::vector<vec2> st = points(l);
    for (int k = 0; k < m * m; ++k) {
      const double s = st[k].x, t = st[k].y;
      const vec3 y = bilinear(c, s, t);
      // The bilinear map's area element dA = |dy/ds x dy/dt| ds dt; the stratum has ds dt = 1 / m^2.
      const vec3 ds = (1 - t) * (c[1] - c[0]) + t * (c[2] - c[3]);
      const vec3 dt = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
      const vec3 normal_area = cross(ds, dt);  // the light's normal times its area element
      const vec3 to_light = y - x;
      const double r2 = dot(to_light, to_light);
      const double cos_x = dot(n, to_light), cos_l_dA = -dot(normal_area, to_light);  // both times r
      if (cos_x <= 0 || cos_l_dA <= 0 || !unoccluded(eye, x, y)) continue;
      // (E / pi) cos_x cos_l dA / r^2, with the two cosines' 1/r each folded in: / r^4.
      H += light.emission / pi * (cos_x * cos_l_dA / (r2 * r2)) / double(m * m);
    }
  }
  return H;
}

}  // namespace

Color irradiance_by_shadow_rays(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n,
                                Rng& rng) {
  const int m = lights.cells;
  return irradiance(eye, lights, x, n, [&](std::size_t) {
    std::vector<vec2> st;
    for (int k = 0; k < m * m; ++k) {
      const double s = (k % m + rng.uniform()) / m, t = (k / m + rng.uniform()) / m;
      st.emplace_back(s, t);
    }
    return st;
  });
}

Color irradiance_by_shadow_rays(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n,
                                PixelSample& sample, int depth) {
  const int count = static_cast<int>(lights.lights.size());
  return irradiance(eye, lights, x, n, [&](std::size_t l) {
    return light_samples({LightSampling::Jittered, lights.cells}, sample, shadow_dimension(depth, int(l), count));
  });
}

}  // namespace gi
