#include "gi/pathtrace/path_integrator.hpp"

#include <stdexcept>
#include <string>

#include "gi/pathtrace/next_event.hpp"
#include "gi/pathtrace/roulette.hpp"

namespace gi {

namespace {

// The size round-off in a point's coordinates is relative to: the coordinates' own,
// plus a thousandth of the scene's scale (scene_scale.hpp) for a point near the
// origin, whose round-off comes from where its ray started. Relative to the scene
// alone, so the same picture at any scale (Cornell box in mm, furnace in m alike);
// 1 + the coordinates on the Cornell box (scale 1024), as it was first tuned.
double size_at(const vec3& p, double scale) {
  return scale / 1024 + max_component(glm::abs(p));
}

// How far a new ray starts off its surface, along the normal on the side it leaves
// from: 1e-9 of size_at, so that round-off in the hit point cannot put the origin
// behind the surface.
vec3 offset_origin(const vec3& point, const vec3& n, const vec3& direction, double scale) {
  return point + (dot(direction, n) > 0 ? 1e-9 : -1e-9) * size_at(point, scale) * n;
}

// Is nothing between x (leaving along n's side) and the light point y?
bool unoccluded(const World& world, const vec3& x, const vec3& n, const vec3& y) {
  const vec3 origin = offset_origin(x, n, y - x, world.scale);
  const vec3 to_light = y - origin;
  const double distance = length(to_light);
  return !any_hit(world, Ray{origin, to_light / distance, 0.0, distance - 1e-9 * size_at(y, world.scale)});
}

}  // namespace

void check(const PathSettings& s) {
  if (s.max_depth < 0 || s.max_depth > 100000)
    throw std::invalid_argument("path tracer: the depth limit must lie in [0, 100000], got " +
                                std::to_string(s.max_depth));
  if (s.roulette_depth < 0)
    throw std::invalid_argument("path tracer: the roulette depth must be >= 0, got " +
                                std::to_string(s.roulette_depth));
}

Color path_radiance(const PathScene& scene, const Ray& camera_ray, const PathSettings& settings, PixelSample& sample) {
  const Scene& s = scene.scene();
  const Lights& lights = scene.lights;
  const bool sample_lights = settings.strategy != Strategy::Bsdf && !lights.lights.empty();
  Color L(0.0), beta(1.0);
  Ray ray = camera_ray;
  bool after_specular = true;  // the camera ray counts as specular: nothing else can see its light
  double p_bsdf = 0;           // density of the direction the last bounce chose
  vec3 previous(0.0);          // where that bounce was
  for (int bounce = 0;; ++bounce) {
    const std::optional<Hit> hit = closest_hit(scene.world, ray);
    if (!hit) {  // the sky: no light sample finds it, so BSDF rays count it in every strategy
      L += beta * s.background;
      break;
    }
    const Material& material = s.materials[hit->material];
    const vec3 wo = -ray.direction;
    const vec3& n = hit->normal;

    // ---- Emission found by this ray -------------------------------------------------
    if (const int k = lights.of_material[hit->material]; k >= 0 && dot(n, wo) > 0) {
      double w_bsdf = 1.0;
      if (!after_specular) {
        const double p_light = area_to_solid_angle(light_pdf_area(lights, s, k, previous), hit->t * hit->t, dot(n, wo));
        w_bsdf = bsdf_sample_weight(settings.strategy, p_bsdf, p_light);
      }
      L += beta * material.emission * w_bsdf;
    }
    if (bounce == settings.max_depth) break;
    const Bsdf bsdf = bsdf_at(material, hit->point);
    const auto dimension = [&](Decision decision) { return path_dimension(static_cast<std::uint32_t>(bounce), decision); };

    // ---- Next-event estimation: a shadow ray to a point on a light -------------------
    if (sample_lights && !is_specular(bsdf)) {
      const double u_choice = sample.get_1d(dimension(Decision::LightChoice));
      const vec2 u = sample.get_2d(dimension(Decision::LightPoint));
      const LightSample y = sample_light(lights, s, hit->point, u_choice, u);
      const DirectSample direct = next_event_estimate(bsdf, hit->point, n, wo, y);
      if (max_component(direct.estimate) > 0 && unoccluded(scene.world, hit->point, n, y.point)) {
        const double w_light = light_sample_weight(settings.strategy, direct.p_light, bsdf_pdf(bsdf, n, wo, direct.wi));
        L += beta * direct.estimate * w_light;
      }
    }

    // ---- BSDF sampling: where the path goes next ------------------------------------
    const vec2 u = sample.get_2d(dimension(Decision::BsdfDirection));
    const double u_lobe = sample.get_1d(dimension(Decision::BsdfLobe));
    const std::optional<BsdfSample> next = sample_bsdf(bsdf, n, wo, u, u_lobe);
    if (!next || max_component(next->weight) <= 0) break;
    beta *= next->weight;
    after_specular = next->specular;
    p_bsdf = next->pdf;
    previous = hit->point;
    ray = Ray{offset_origin(hit->point, n, next->wi, scene.world.scale), next->wi};

    // ---- Possibly terminate the path with Russian roulette ---------------------------
    if (bounce + 1 >= settings.roulette_depth && !russian_roulette(beta, sample.get_1d(dimension(Decision::Roulette))))
      break;
  }
  return L;
}

}  // namespace gi
