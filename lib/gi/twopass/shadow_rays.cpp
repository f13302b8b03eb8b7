#include "gi/twopass/shadow_rays.hpp"

#include <stdexcept>

#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

ShadowRayLights shadow_ray_lights(const Mesh& mesh, int cells) {
  if (cells < 1 || cells > 64) throw std::invalid_argument("shadow rays: cells must lie in [1, 64]");
  ShadowRayLights lights{{}, cells};
  for (const Surface& s : mesh.surfaces)
    if (max_component(s.emission) > 0) lights.lights.push_back(s);
  return lights;
}

Color irradiance_by_shadow_rays(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n,
                                Rng& rng) {
  Color H(0.0);
  const int m = lights.cells;
  for (const Surface& light : lights.lights) {
    const auto& c = light.corners;
    for (int k = 0; k < m * m; ++k) {
      const double s = (k % m + rng.uniform()) / m, t = (k / m + rng.uniform()) / m;
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

}  // namespace gi
