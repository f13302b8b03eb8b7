#pragma once
#include <array>

#include "gi/core/ray.hpp"
#include "gi/scene/material.hpp"

namespace gi {

// Whitted's mirror and glass (lesson 02), without the Phong terms: where a ray meets
// a perfectly specular surface, the light it carries comes along one or two new rays.
//   mirror  one ray along the reflection, weight k_r
//   glass   the reflected ray with weight F and the refracted one (Snell) with 1 - F,
//           F the exact Fresnel fraction (1 under total internal reflection: one ray),
//           both times the glass's transmission filter
// The new rays start a hair off the surface, on the side they leave by: 1e-6 of the
// distance the ray came plus offset_floor(scale), `scale` the scene's (World::scale,
// scene_scale.hpp), so that the same scene at any scale draws the same picture.
struct SpecularRay {
  Color weight;
  Ray ray;
};
struct SpecularRays {
  std::array<SpecularRay, 2> rays;
  int count = 0;
};
SpecularRays specular_rays(const Material& material, const Ray& ray, const Hit& hit, double scale);

}  // namespace gi
