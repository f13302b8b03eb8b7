#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/render/render_pass.hpp"
#include "gi/twopass/eye_world.hpp"
#include "gi/twopass/shadow_rays.hpp"
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
  int samples = 2;         // n x n jittered eye rays per pixel, box filter (1..16): render_pass's Jittered
  IndirectLight indirect = IndirectLight::FinalGather;
  int light_cells = 2;     // cells^2 shadow rays per light at every diffuse hit (1..64)
  int gather_strata = 6;   // FinalGather: strata^2 rays at every diffuse hit (1..64)
  int max_depth = 8;       // specular bounces (0..64)
  // The numbers the eye rays' points in the pixel and the shadow rays' points on the
  // lights read (sample_stream.hpp); the final gather draws from the pixel's stream,
  // as exercise 16.2 draws it, whatever the sequence.
  SamplerKind sequence = SamplerKind::Independent;
};
void check(const TwoPassSettings& settings);  // throws std::invalid_argument

// H_a above, from the mesh's surfaces.
Color ambient_irradiance(const Mesh& mesh);

// The eye pass as a radiance function (render_pass.hpp): the radiance arriving along an
// eye ray, by the rules above; its shadow rays read the sample's numbers, at a dimension
// per specular depth and light, and its gather rays draw from the pixel's stream. The
// hand-off must be of `scene`'s surfaces, and outlive it.
class EyePass {
 public:
  EyePass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings);
  Color operator()(const Ray& ray, PixelSample& sample) const { return radiance(ray, 0, sample); }

 private:
  Color radiance(const Ray& ray, int depth, PixelSample& sample) const;
  Color specular(const Ray& ray, const EyeHit& hit, int depth, PixelSample& sample) const;

  const RadiosityHandoff& handoff_;
  TwoPassSettings settings_;
  EyeWorld eye_;
  ShadowRayLights lights_;
  Color ambient_;
};

// The picture, linear radiance per pixel: the eye pass through every pixel, pixel i
// reading the numbers of pixel i of `seed` in settings.sequence, on `threads` threads
// (the same bytes for any count).
Image render_two_pass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings,
                      std::uint64_t seed, int threads);

}  // namespace gi
