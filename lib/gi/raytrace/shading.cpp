#include "gi/raytrace/shading.hpp"

#include <cmath>

#include "gi/core/not_implemented.hpp"

namespace gi {

Color phong(const Material& material, const Color& kd, const vec3& n, const vec3& l, const vec3& v,
            const Color& light_intensity) {
  // BEGIN EXERCISE 2.4 Phong shading
  const double n_dot_l = dot(n, l);
  if (n_dot_l <= 0) return Color(0.0);  // the light is behind the surface
  Color colour = kd * n_dot_l;
  if (max_component(material.specular) > 0) {  // a matte surface has no highlight: spare the pow
    const vec3 r = 2.0 * n_dot_l * n - l;       // L mirrored about N
    const double r_dot_v = dot(r, v);
    if (r_dot_v > 0) colour += material.specular * std::pow(r_dot_v, material.shininess);
  }
  return light_intensity * colour;
  // END EXERCISE 2.4
}

Ray shadow_ray(const vec3& point, const vec3& n, const vec3& light_position, double epsilon) {
  // BEGIN EXERCISE 2.5 shadow ray
  const vec3 side = dot(light_position - point, n) >= 0 ? n : -n;
  const vec3 origin = point + epsilon * side;
  const vec3 to_light = light_position - origin;
  const double distance = length(to_light);
  return Ray{origin, to_light / distance, 0.0, distance - epsilon};
  // END EXERCISE 2.5
}

bool visible(const World& world, const vec3& point, const vec3& n, const vec3& light_position, double epsilon) {
  return !any_hit(world, shadow_ray(point, n, light_position, epsilon));
}

}  // namespace gi
