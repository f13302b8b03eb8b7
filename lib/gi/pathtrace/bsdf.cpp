#include "gi/pathtrace/bsdf.hpp"

#include "gi/core/onb.hpp"
#include "gi/core/sampling.hpp"
#include "gi/raytrace/optics.hpp"

namespace gi {

namespace {

bool same_side(const vec3& n, const vec3& wo, const vec3& wi) { return dot(n, wo) * dot(n, wi) > 0; }

// Smooth glass. The side wo is on decides which index is which: outside (wo along the
// outward normal) the light goes from air into glass, inside from glass into air.
std::optional<BsdfSample> sample_dielectric(const Bsdf& bsdf, const vec3& n, const vec3& wo, double u_choice) {
  const bool outside = dot(wo, n) > 0;
  const vec3 n_wo = outside ? n : -n;  // the normal on wo's side
  const double eta_o = outside ? 1.0 : bsdf.ior, eta_t = outside ? bsdf.ior : 1.0;
  const double fresnel = fresnel_dielectric(dot(wo, n_wo), eta_o, eta_t);
  const std::optional<vec3> transmitted = refract(-wo, n_wo, eta_o / eta_t);
  if (!transmitted || u_choice < fresnel) {
    // Reflected with probability F, carrying F: the weight F / F is 1.
    return BsdfSample{reflect(-wo, n_wo), Color(1.0), transmitted ? fresnel : 1.0, true};
  }
  // Transmitted with probability 1 - F, carrying (1 - F) times the filter. Radiance is
  // squeezed into a narrower cone on entering a denser medium: L / eta^2 is what is
  // conserved across the boundary, so the radiance seen from wo's side is
  // (eta_o / eta_t)^2 times the radiance arriving along wi. A path that enters and
  // leaves a glass ball gets both factors, and they cancel.
  const double squeeze = (eta_o / eta_t) * (eta_o / eta_t);
  return BsdfSample{normalize(*transmitted), squeeze * bsdf.albedo, 1.0 - fresnel, true};
}

// The mirror direction of wo about the normal on wo's side: the axis of the Phong lobe.
vec3 lobe_axis(const vec3& n, const vec3& wo) { return reflect(-wo, dot(wo, n) > 0 ? n : -n); }

}  // namespace

bool is_glossy(const Material& material) {
  return max_component(material.diffuse) <= 0 && material.checker_size <= 0 && max_component(material.specular) > 0;
}

Bsdf bsdf_at(const Material& material, const vec3& point) {
  if (material.is_dielectric()) return {BsdfKind::Dielectric, material.transmission, material.ior};
  if (max_component(material.mirror) > 0) return {BsdfKind::Mirror, material.mirror, 1.0};
  if (is_glossy(material)) return {BsdfKind::Glossy, material.specular, 1.0, material.shininess};
  return {BsdfKind::Lambertian, diffuse_at(material, point), 1.0};
}

Color bsdf_f(const Bsdf& bsdf, const vec3& n, const vec3& wo, const vec3& wi) {
  if (is_specular(bsdf) || !same_side(n, wo, wi)) return Color(0.0);
  if (bsdf.kind == BsdfKind::Glossy) {  // f = k_s (n + 2) / (2 pi) cos^n(alpha)
    const double cos_alpha = dot(wi, lobe_axis(n, wo));
    if (!(cos_alpha > 0)) return Color(0.0);
    return bsdf.albedo * ((bsdf.exponent + 2) / (2 * pi) * std::pow(cos_alpha, bsdf.exponent));
  }
  return bsdf.albedo * inv_pi;  // f = rho / pi
}

double bsdf_pdf(const Bsdf& bsdf, const vec3& n, const vec3& wo, const vec3& wi) {
  if (is_specular(bsdf) || !same_side(n, wo, wi)) return 0.0;
  if (bsdf.kind == BsdfKind::Glossy) return phong_lobe_pdf(dot(wi, lobe_axis(n, wo)), bsdf.exponent);
  return cosine_hemisphere_pdf(std::abs(dot(n, wi)));
}

std::optional<BsdfSample> sample_bsdf(const Bsdf& bsdf, const vec3& n, const vec3& wo, vec2 u, double u_choice) {
  switch (bsdf.kind) {
    case BsdfKind::Lambertian: {
      // Cosine-weighted around the normal on wo's side: f cos / p = rho, the same for
      // every direction, which is why a diffuse path's throughput never jumps.
      const Onb frame(dot(n, wo) >= 0 ? n : -n);
      const vec3 local = sample_cosine_hemisphere(u);
      const double pdf = cosine_hemisphere_pdf(local.z);
      if (!(pdf > 0)) return std::nullopt;
      const vec3 wi = frame.to_world(local);
      return BsdfSample{wi, bsdf_f(bsdf, n, wo, wi) * local.z / pdf, pdf, false};
    }
    case BsdfKind::Mirror: {
      const vec3 n_wo = dot(wo, n) > 0 ? n : -n;
      return BsdfSample{reflect(-wo, n_wo), bsdf.albedo, 1.0, true};
    }
    case BsdfKind::Dielectric: return sample_dielectric(bsdf, n, wo, u_choice);
    case BsdfKind::Glossy: {
      // Around the mirror direction by the lobe. A direction below the surface carries
      // nothing (f = 0 there); the lobe's density still counts it, so none is redrawn.
      // f cos / p = k_s (n + 2) / (n + 1) cos(theta_i).
      const vec3 local = sample_phong_lobe(u, bsdf.exponent);
      const vec3 wi = Onb(lobe_axis(n, wo)).to_world(local);
      const double pdf = phong_lobe_pdf(local.z, bsdf.exponent);
      if (!same_side(n, wo, wi) || !(pdf > 0)) return std::nullopt;
      return BsdfSample{wi, bsdf_f(bsdf, n, wo, wi) * std::abs(dot(n, wi)) / pdf, pdf, false};
    }
  }
  return std::nullopt;
}

}  // namespace gi
