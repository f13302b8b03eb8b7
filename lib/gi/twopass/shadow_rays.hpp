#pragma once
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/render/render_pass.hpp"
#include "gi/twopass/eye_world.hpp"

namespace gi {

// Direct light by shadow rays, lesson 04's soft shadows in physical units: the
// irradiance at x (unit normal n) from every light l (a surface with exitance E_l > 0,
// radiance E_l / pi) is the integral over the light's area
//   H(x) = sum_l  integral over A_l of (E_l / pi) cos_x cos_l / r^2  V(x, y) dA_y
// estimated with the light cut into cells x cells strata, one jittered point y per
// stratum (an unbiased estimate; the strata keep its noise low) and a shadow ray to
// it. V is 0 when anything -- a wall, a block, a sphere -- is in between: the shadows
// are sharp where the light is small, soft where it is large, and a glass sphere casts
// a black shadow (its caustic is no path this estimate follows).
struct ShadowRayLights {
  std::vector<Surface> lights;
  int cells = 4;  // strata per side: cells^2 shadow rays per light and estimate (1..64)
};

// The lights of a mesh. Throws std::invalid_argument for cells outside 1..64.
ShadowRayLights shadow_ray_lights(const Mesh& mesh, int cells);

// H(x) by cells^2 shadow rays per light, drawn from rng.
Color irradiance_by_shadow_rays(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n,
                                Rng& rng);
// The same with the points read from `sample`'s numbers: light l's cells^2 points are one
// set of the film's sequence at dimension shadow_dimension(depth, l, lights), offsets in
// the cells as Whitted's jittered shadow rays take them (raytrace/light_sample_numbers.hpp).
// With independent numbers they are the pixel's stream drawn as above, to the byte.
Color irradiance_by_shadow_rays(const EyeWorld& eye, const ShadowRayLights& lights, const vec3& x, const vec3& n,
                                PixelSample& sample, int depth);

}  // namespace gi
