#include "gi/twopass/final_gather.hpp"

#include "gi/core/not_implemented.hpp"
#include "gi/core/onb.hpp"
#include "gi/core/sampling.hpp"
#include "gi/twopass/specular.hpp"

namespace gi {

Color reflected_radiosity_along(const EyeWorld& eye, const RadiosityHandoff& handoff, const Ray& ray, int depth) {
  const auto y = first_hit(eye, ray);
  if (!y) return Color(0.0);  // the void
  if (y->element >= 0)
    return dot(ray.direction, y->hit.normal) < 0 ? reflected_radiosity_at(handoff, y->element, y->hit.point)
                                                  : Color(0.0);  // the back of a surface
  if (depth >= specular_gather_depth) return Color(0.0);
  const SpecularRays next = specular_rays(eye.world.scene.materials[y->hit.material], ray, y->hit, eye.world.scale);
  Color sum(0.0);
  for (int i = 0; i < next.count; ++i)
    sum += next.rays[i].weight * reflected_radiosity_along(eye, handoff, next.rays[i].ray, depth + 1);
  return sum;
}

Color final_gather(const EyeWorld& eye, const RadiosityHandoff& handoff, const vec3& x, const vec3& n, int strata,
                   Rng& rng) {
  const Onb frame(n);
  const int rays = strata * strata;
  Color sum(0.0);
  // BEGIN EXERCISE 16.2 the final-gather estimate
  for (int k = 0; k < rays; ++k) {
    const double v = rng.uniform(), u0 = rng.uniform();  // one at a time, v first, whatever the compiler
    const vec2 u((k % strata + u0) / strata, (k / strata + v) / strata);
    const vec3 w = frame.to_world(sample_cosine_hemisphere(u));
    const Ray gather{x, w};
    const auto y = first_hit(eye, gather);
    if (!y) continue;  // the void
    if (y->element < 0) {
      sum += reflected_radiosity_along(eye, handoff, gather);  // a sphere: on to the surface it shows
    } else if (dot(w, y->hit.normal) < 0) {                    // the front of a diffuse surface
      // L_r cos / p with p = cos / pi: (B - E)(y) / pi * pi = (B - E)(y)
      sum += reflected_radiosity_at(handoff, y->element, y->hit.point);
    }
  }
  // END EXERCISE 16.2
  return sum / double(rays);
}

}  // namespace gi
