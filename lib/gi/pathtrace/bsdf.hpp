#pragma once
#include <optional>

#include "gi/core/math.hpp"
#include "gi/scene/material.hpp"

namespace gi {

// The path tracer's three surfaces, each with its BSDF f, a way to sample it and the
// density of that sampling, kept together:
//   Lambertian  f = rho / pi on the side the light comes from (both sides of a surface
//               reflect), sampled by the cosine: p(wi) = cos(theta_i) / pi
//   Mirror      all light leaves along the reflection of wo, times k_r
//   Dielectric  smooth glass: reflected with the exact Fresnel fraction F of lesson 02,
//               transmitted (Snell) with 1 - F; the choice is made with probability F
//   Glossy      the normalised Phong lobe (Lafortune and Willems 1994) around the mirror
//               direction r of wo: f = k_s (n + 2) / (2 pi) cos^n(alpha), alpha the
//               angle between wi and r; sampled by the lobe, p(wi) = (n + 1) / (2 pi)
//               cos^n(alpha) (sampling.hpp). n = 10 is rough, n = 10 000 nearly a mirror.
// Mirror and dielectric are specular: f is a delta, f() and pdf() are 0 for every
// direction a caller could pick, and only sample_bsdf finds their one direction.
// All directions are unit vectors pointing away from the surface: wo towards the viewer,
// wi towards where the light comes from; n is the surface's outward unit normal.
enum class BsdfKind { Lambertian, Mirror, Dielectric, Glossy };

struct Bsdf {
  BsdfKind kind = BsdfKind::Lambertian;
  Color albedo{0.0};  // Lambertian: rho; Mirror: k_r; Dielectric: the transmission filter
  double ior = 1.5;   // Dielectric: index inside the surface (outside is air, 1)
  double exponent = 1;  // Glossy: the Phong exponent n; albedo is k_s
};

// A scene material as the path tracer sees it: a dielectric if it transmits, else a
// mirror if it reflects (its small diffuse part dropped), else glossy if it is nothing
// but a Phong highlight (k_d = 0, k_s > 0: is_glossy), else Lambertian with rho = k_d at
// the point (checkerboards included). The highlight beside a diffuse part, and ambient
// terms, have no place in a physical model and are ignored.
Bsdf bsdf_at(const Material& material, const vec3& point);
bool is_glossy(const Material& material);

inline bool is_specular(const Bsdf& bsdf) { return bsdf.kind == BsdfKind::Mirror || bsdf.kind == BsdfKind::Dielectric; }

// f(wo, wi), per colour channel; 0 for the specular kinds.
Color bsdf_f(const Bsdf& bsdf, const vec3& n, const vec3& wo, const vec3& wi);

// The density (solid angle) with which sample_bsdf picks wi; 0 for the specular kinds.
double bsdf_pdf(const Bsdf& bsdf, const vec3& n, const vec3& wo, const vec3& wi);

struct BsdfSample {
  vec3 wi;
  Color weight;  // f |cos theta_i| / pdf: what the path's throughput is multiplied by
  double pdf;    // solid angle; for a specular choice, the probability of that choice
  bool specular;
};

// Draws wi for the light arriving along it: u picks the direction, u_choice picks
// reflection or transmission at a dielectric. Nothing when the sample carries no
// light (a Lambertian sample exactly on the horizon).
std::optional<BsdfSample> sample_bsdf(const Bsdf& bsdf, const vec3& n, const vec3& wo, vec2 u, double u_choice);

}  // namespace gi
