#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/twopass/handoff.hpp"
#include "gi/twopass/two_pass_scene.hpp"

namespace gi {

// Pass 2, the combined renderer: rays from the eye, traced as Whitted traces them
// through mirror and glass, and at the first diffuse surface they meet
//   L(x) = E(x) / pi  +  rho(x) H(x) / pi  +  indirect
// with H(x), the direct light, by shadow rays to the area light (shadow_rays.hpp) --
// sharp where the light is small, blocked by the spheres too -- and the indirect light
// taken one of three ways:
//   Ambient      the ray tracer alone: Whitted's constant ambient term, rho H_a / pi,
//                with H_a the lecture's estimate of the light that has bounced at
//                least once, spread evenly: H_a = rho_avg / (1 - rho_avg) * sum_i E_i A_i / sum_i A_i
//   Mesh         read off the radiosity solution: (B - E - D)(x) / pi (handoff.hpp)
//   FinalGather  one bounce of cosine-weighted rays reading (B - E) where they land:
//                rho H_ind(x) / pi (final_gather.hpp)
// Mirror: L = k_r L(reflected ray). Glass: L = F L(reflected) + (1 - F) L(transmitted),
// with the exact Fresnel F of lesson 02 (1 under total internal reflection), times the
// glass's transmission filter. A ray past max_depth specular bounces, or that leaves
// the scene, carries nothing. The plain ray tracer (raytrace/) never reads radiosity:
// this file is the one place where both passes meet.
enum class IndirectLight { Ambient, Mesh, FinalGather };
std::string name(IndirectLight indirect);  // "ambient", "mesh", "final gather"

struct TwoPassSettings {
  int width = 128, height = 128;
  int samples = 2;         // n x n jittered eye rays per pixel, box filter (1..16)
  IndirectLight indirect = IndirectLight::FinalGather;
  int light_cells = 2;     // cells^2 shadow rays per light at every diffuse hit (1..64)
  int gather_strata = 6;   // FinalGather: strata^2 rays at every diffuse hit (1..64)
  int max_depth = 8;       // specular bounces (0..64)
  int threads = 0;
  std::uint64_t seed = 1;  // pixel (x, y) draws from stream y * width + x: the same bytes for any thread count
};
void check(const TwoPassSettings& settings);  // throws std::invalid_argument

// H_a above, from the mesh's surfaces.
Color ambient_irradiance(const Mesh& mesh);

// The picture, linear radiance per pixel. The hand-off must be of `scene`'s surfaces.
Image render_two_pass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings);

}  // namespace gi
