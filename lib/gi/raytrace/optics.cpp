#include "gi/raytrace/optics.hpp"

#include <cmath>

#include "gi/core/not_implemented.hpp"

namespace gi {

vec3 reflect(const vec3& d, const vec3& n) {
  // BEGIN EXERCISE 2.1 reflection direction
  return d - 2.0 * dot(d, n) * n;
  // END EXERCISE 2.1
}

std::optional<vec3> refract(const vec3& d, const vec3& n, double eta) {
  // With cos_i = -d.n:  sin^2(theta_t) = eta^2 (1 - cos_i^2)  and
  //   t = eta d + (eta cos_i - cos_t) n.
  // BEGIN EXERCISE 2.2 refraction direction with total internal reflection
  const double cos_i = -dot(d, n);
  const double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t > 1.0) return std::nullopt;  // total internal reflection
  const double cos_t = std::sqrt(1.0 - sin2_t);
  return eta * d + (eta * cos_i - cos_t) * n;
  // END EXERCISE 2.2
}

double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
  // r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)
  // r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t),   F = (r_s^2 + r_p^2) / 2
  // BEGIN EXERCISE 2.3 Fresnel reflectance of a dielectric
  cos_i = std::min(1.0, std::abs(cos_i));
  const double sin_t = eta_i / eta_t * std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
  if (sin_t >= 1.0) return 1.0;  // total internal reflection: everything is reflected
  const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
  const double r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  const double r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
  // END EXERCISE 2.3
}

double fresnel_schlick(double cos_i, double eta_i, double eta_t) {
  double c = std::min(1.0, std::abs(cos_i));
  if (eta_i > eta_t) {
    // Leaving the denser medium: Schlick's formula needs the angle on the dense side,
    // i.e. the transmitted angle, which does not exist past the critical angle.
    const double sin_t = eta_i / eta_t * std::sqrt(1.0 - c * c);
    if (sin_t >= 1.0) return 1.0;
    c = std::sqrt(1.0 - sin_t * sin_t);
  }
  const double f0 = (eta_i - eta_t) * (eta_i - eta_t) / ((eta_i + eta_t) * (eta_i + eta_t));
  return f0 + (1.0 - f0) * std::pow(1.0 - c, 5);
}

}  // namespace gi
