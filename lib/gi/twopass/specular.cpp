#include "gi/twopass/specular.hpp"

#include "gi/raytrace/optics.hpp"
#include "gi/scene/scene_scale.hpp"

namespace gi {

SpecularRays specular_rays(const Material& m, const Ray& ray, const Hit& hit, double scale) {
  const vec3& d = ray.direction;
  const bool entering = dot(d, hit.normal) < 0;
  const vec3 n = entering ? hit.normal : -hit.normal;  // on the side d comes from
  const double eps = 1e-6 * hit.t + offset_floor(scale);
  SpecularRays out;
  const auto add = [&](const Color& weight, const vec3& side, const vec3& w) {
    out.rays[out.count++] = {weight, Ray{hit.point + eps * side, w}};
  };
  if (!m.is_dielectric()) {
    add(m.mirror, n, reflect(d, n));
    return out;
  }
  const double eta_i = entering ? 1.0 : m.ior, eta_t = entering ? m.ior : 1.0;
  const double F = fresnel_dielectric(-dot(d, n), eta_i, eta_t);
  add(F * m.transmission, n, reflect(d, n));
  if (const auto t = refract(d, n, eta_i / eta_t); t && F < 1) add((1 - F) * m.transmission, -n, *t);
  return out;
}

}  // namespace gi
