#include "gi/pathtrace/next_event.hpp"

#include "gi/core/not_implemented.hpp"
#include "gi/core/sampling.hpp"

namespace gi {

DirectSample next_event_estimate(const Bsdf& bsdf, const vec3& x, const vec3& n, const vec3& wo, const LightSample& y) {
  // BEGIN EXERCISE 14.4 next-event estimation with the light's density in area measure
  const vec3 to_light = y.point - x;
  const double distance_squared = dot(to_light, to_light);
  const double distance = std::sqrt(distance_squared);
  const vec3 wi = to_light / distance;
  const double cos_light = -dot(y.normal, wi);
  if (!(cos_light > 0)) return {wi, distance, 0.0, Color(0.0)};
  const double p_light = area_to_solid_angle(y.pdf_area, distance_squared, cos_light);
  const Color f = bsdf_f(bsdf, n, wo, wi);
  return {wi, distance, p_light, f * y.radiance * std::abs(dot(n, wi)) / p_light};
  // END EXERCISE 14.4
}

}  // namespace gi
