#include "gi/raytrace/whitted.hpp"

#include "gi/accel/world_fast.hpp"
#include "gi/raytrace/light_sample_numbers.hpp"
#include "gi/raytrace/optics.hpp"
#include "gi/raytrace/shading.hpp"
#include "gi/raytrace/whitted_fast.hpp"

namespace gi {

// Local illumination: ambient plus the Phong term of every light the shadow rays reach.
Color shade_locally(const World& world, const Hit& hit, const vec3& n, const vec3& to_eye,
                    const TraceSettings& settings, RayCounts& counts, PixelSample& sample, int depth) {
  const Material& material = world.scene.materials[hit.material];
  const Color kd = diffuse_at(material, hit.point);
  Color colour = material.emission + material.ambient * kd * world.scene.ambient_light;
  const double epsilon = settings.epsilon * world.scale;  // relative to the scene's size (scene_scale.hpp)
  for (const PointLight& light : world.scene.lights) {
    const Ray shadow = shadow_ray(hit.point, n, light.position, epsilon);
    const vec3& l = shadow.direction;
    if (dot(n, l) <= 0) continue;  // light behind the surface: no shadow ray needed
    counts.count(RayKind::Shadow, depth);
    if (!any_hit(world, shadow)) colour += phong(material, kd, n, l, to_eye, light.intensity);
  }
  const std::vector<QuadLight>& area_lights = world.scene.area_lights;
  for (std::size_t l = 0; l < area_lights.size(); ++l) {
    const QuadLight& light = area_lights[l];
    const auto reaches = [&](const vec3& y) {  // S(x, y): does the shadow ray get to y?
      const Ray shadow = shadow_ray(hit.point, n, y, epsilon);
      if (dot(n, shadow.direction) <= 0) return false;  // y is behind the surface
      counts.count(RayKind::Shadow, depth);
      return !any_hit(world, shadow);
    };
    const auto point_light_at = [&](const vec3& y) {
      return phong(material, kd, n, normalize(y - hit.point), to_eye, light.intensity);
    };
    const std::uint32_t dimension = shadow_dimension(depth, int(l), int(area_lights.size()));
    colour += soft_shadow_estimate(light, light_samples(settings.soft_shadows, sample, dimension), reaches,
                                   point_light_at);
  }
  return colour;
}

Color trace(const World& world, const Ray& ray, const TraceSettings& settings, RayCounts& counts,
            PixelSample& sample, int depth, const Color& contribution) {
  // The nearest hit and the local term, or the same by the tuned code of the *_fast files.
  const std::optional<Hit> hit = settings.fast_queries ? closest_hit_fast(world, ray) : closest_hit(world, ray);
  if (!hit) return world.scene.background;

  const Material& material = world.scene.materials[hit->material];
  const bool entering = dot(ray.direction, hit->normal) < 0;
  const vec3 n = entering ? hit->normal : -hit->normal;  // the normal on the ray's side
  const vec3 to_eye = -ray.direction;
  Color colour = settings.fast_queries ? shade_locally_fast(world, *hit, n, to_eye, settings, counts, sample, depth)
                                       : shade_locally(world, *hit, n, to_eye, settings, counts, sample, depth);
  if (depth >= settings.max_depth) return colour;

  // How much reflected and transmitted light reaches this point's colour.
  Color k_r = material.mirror;
  Color k_t(0.0);
  std::optional<vec3> transmitted;
  if (material.is_dielectric()) {
    // Outside is air (index 1); inside is the material.
    const double eta_i = entering ? 1.0 : material.ior;
    const double eta_t = entering ? material.ior : 1.0;
    const double fresnel = fresnel_dielectric(-dot(ray.direction, n), eta_i, eta_t);
    transmitted = refract(ray.direction, n, eta_i / eta_t);
    k_r += Color(fresnel);
    if (transmitted) k_t = (1.0 - fresnel) * material.transmission;
  }

  // Spawn a secondary ray only where it can still change the pixel.
  auto worth_tracing = [&](const Color& k) {
    const double c = max_component(contribution * k);
    return c > 0 && c >= settings.min_contribution;
  };
  const double epsilon = settings.epsilon * world.scale;  // relative to the scene's size (scene_scale.hpp)
  if (worth_tracing(k_r)) {
    counts.count(RayKind::Reflected, depth + 1);
    const Ray reflected{hit->point + epsilon * n, reflect(ray.direction, n)};
    colour += k_r * trace(world, reflected, settings, counts, sample, depth + 1, contribution * k_r);
  }
  if (transmitted && worth_tracing(k_t)) {
    counts.count(RayKind::Transmitted, depth + 1);
    const Ray refracted{hit->point - epsilon * n, normalize(*transmitted)};
    colour += k_t * trace(world, refracted, settings, counts, sample, depth + 1, contribution * k_t);
  }
  return colour;
}

Color trace(const World& world, const Ray& ray, const TraceSettings& settings, RayCounts& counts, Rng& rng,
            int depth, const Color& contribution) {
  PixelSample sample = stream_sample(rng);
  return trace(world, ray, settings, counts, sample, depth, contribution);
}

}  // namespace gi
