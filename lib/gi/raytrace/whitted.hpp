#pragma once
#include "gi/core/ray.hpp"
#include "gi/core/rng.hpp"
#include "gi/raytrace/ray_counts.hpp"
#include "gi/raytrace/soft_shadows.hpp"
#include "gi/render/render_pass.hpp"
#include "gi/accel/world.hpp"

namespace gi {

// When recursion stops: at a depth limit, and when a ray could no longer change the
// pixel visibly (its contribution -- the product of the k_r and k_t factors along
// its path -- is below a threshold in every channel).
struct TraceSettings {
  int max_depth = 8;               // 0: eye rays and shadow rays only
  double min_contribution = 0.0;   // 0: never stop early
  // How far secondary rays start off a surface, as a fraction of the scene's scale
  // (scene_scale.hpp; World::scale): 1e-6 scene units at Whitted's scale 16.
  double epsilon = 6.25e-8;
  SoftShadowSettings soft_shadows;  // shadow rays per area light (lesson 04)
  bool fast_queries = false;        // nearest hits and local shading by the *_fast files
                                    // (world_fast.hpp, whitted_fast.hpp): the same picture to
                                    // the byte, sooner
};

// Whitted's recursive ray tracer. Returns the radiance seen along `ray`:
//   I = k_a I_a + sum_l S_l I_l [k_d N.L + k_s (R.V)^n] + k_r I_r + k_t I_t
// `depth` is the number of reflections/refractions that led to this ray and
// `contribution` how much of it reaches the pixel. Counts every ray it casts; the shadow
// rays' points on area lights read `sample`'s numbers (light_sample_numbers.hpp).
Color trace(const World& world, const Ray& ray, const TraceSettings& settings, RayCounts& counts,
            PixelSample& sample, int depth = 0, const Color& contribution = Color(1.0));
// The same with the independent numbers of `rng` alone (stream_sample).
Color trace(const World& world, const Ray& ray, const TraceSettings& settings, RayCounts& counts, Rng& rng,
            int depth = 0, const Color& contribution = Color(1.0));

// trace()'s local term at `hit`, seen from `to_eye`, with `n` the normal on the viewer's
// side: emission + k_a I_a + sum_l S_l I_l [k_d N.L + k_s (R.V)^n], each S_l a shadow ray
// (counted at `depth`), area lights sampled with `sample`'s numbers.
Color shade_locally(const World& world, const Hit& hit, const vec3& n, const vec3& to_eye,
                    const TraceSettings& settings, RayCounts& counts, PixelSample& sample, int depth);

}  // namespace gi
