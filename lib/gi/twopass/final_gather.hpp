#pragma once
#include "gi/core/rng.hpp"
#include "gi/twopass/eye_world.hpp"
#include "gi/twopass/handoff.hpp"

namespace gi {

// The final gather (Chen, Rushmeier, Miller and Turner 1991): instead of reading the
// indirect light at x off the mesh -- where the mesh's tiles and blurry shadows show
// -- gather it one bounce later. The irradiance at x from light that has been
// reflected at least once is
//   H_ind(x) = integral over the hemisphere of L_r(y(w)) cos(theta) dw,
//   L_r(y) = (B - E)(y) / pi   the light y reflects (its own emission is the shadow
//                              rays' to count)
// With directions drawn by the cosine, p(w) = cos(theta) / pi, each ray's L cos / p is
//   (B - E)(y) / pi * cos / (cos / pi) = (B - E)(y),
// so H_ind(x) ~ (1/N) sum_k (B - E)(y_k), N = strata^2 rays, one jittered direction
// per stratum of the unit square. The mesh's errors are now seen from a distance,
// averaged over many elements. Rays that leave the scene or meet the back of a surface
// read 0. A ray that meets a sphere is followed through mirror and glass
// (reflected_radiosity_along) to the diffuse surface it ends on: the walls the mirror
// shows do light x. Light that comes to x straight from the lamp by way of a sphere (an
// L S D path: a caustic, or the lamp's image in the mirror) is in neither pass.
// `x` must be lifted off its surface; n is its unit normal.
Color final_gather(const EyeWorld& eye, const RadiosityHandoff& handoff, const vec3& x, const vec3& n, int strata,
                   Rng& rng);

// (B - E) where `ray` ends, through at most specular_gather_depth specular bounces,
// weighted as specular.hpp weighs them; 0 in the void, on a back face, or past the depth.
inline constexpr int specular_gather_depth = 4;
Color reflected_radiosity_along(const EyeWorld& eye, const RadiosityHandoff& handoff, const Ray& ray, int depth = 0);

}  // namespace gi
