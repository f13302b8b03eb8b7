#pragma once
// Sampling routines and their densities, kept side by side as pbrt's sampling.h and
// Nori's warp.h keep them. Each sample_x(u) turns uniform numbers u in [0, 1)^2 into
// a point of its domain; x_pdf, directly below it, is the density of those points in
// the measure named:
//   solid angle  per steradian, for directions
//   area         per unit area, for points on a surface
// Where the map can be undone, invert_x_sample gives u back (the tests round-trip it).
// Directions come out in a local frame around +z (a normal, or the way to a light):
// Onb (onb.hpp) turns them into world space. Every density is tested against its
// sampler by a chi-square test in tests/core/sampling_test.cpp.
#include <vector>

#include "gi/core/math.hpp"
#include "gi/core/not_implemented.hpp"

namespace gi {

// Uniform over the hemisphere z >= 0: z = cos(theta) is uniform in [0, 1] (Archimedes:
// equal heights cut equal areas), phi = 2 pi u.y.
inline vec3 sample_uniform_hemisphere(vec2 u) {
  const double z = u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
// Solid angle: 1 / (2 pi) on the hemisphere.
inline double uniform_hemisphere_pdf() { return 1 / (2 * pi); }
inline vec2 invert_uniform_hemisphere_sample(const vec3& w) {
  const double phi = std::atan2(w.y, w.x);
  return {w.z, (phi < 0 ? phi + 2 * pi : phi) / (2 * pi)};
}

// Cosine-weighted over the hemisphere z >= 0 (Malley's method): a uniform point of the
// unit disc, r = sqrt(u.x) and phi = 2 pi u.y, lifted straight up onto the hemisphere.
// The lift turns the disc's uniform area density into cos(theta) / pi per steradian.
inline vec3 sample_cosine_hemisphere(vec2 u) {
  // BEGIN EXERCISE 14.1 cosine-weighted hemisphere sampling
  const double r = std::sqrt(u.x), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u.x))};
  // END EXERCISE 14.1
}
// Solid angle: p(w) = cos(theta) / pi for cos(theta) = w.z > 0, and 0 below the horizon.
inline double cosine_hemisphere_pdf(double cos_theta) {
  // BEGIN EXERCISE 14.2 the density of cosine-weighted sampling
  return cos_theta > 0 ? cos_theta * inv_pi : 0.0;
  // END EXERCISE 14.2
}
inline vec2 invert_cosine_hemisphere_sample(const vec3& w) {
  const double phi = std::atan2(w.y, w.x);
  return {w.x * w.x + w.y * w.y, (phi < 0 ? phi + 2 * pi : phi) / (2 * pi)};
}

// Uniform over the whole sphere: z uniform in [-1, 1].
inline vec3 sample_uniform_sphere(vec2 u) {
  const double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
// Solid angle: 1 / (4 pi).
inline double uniform_sphere_pdf() { return 1 / (4 * pi); }
inline vec2 invert_uniform_sphere_sample(const vec3& w) {
  const double phi = std::atan2(w.y, w.x);
  return {(1 - w.z) / 2, (phi < 0 ? phi + 2 * pi : phi) / (2 * pi)};
}

// Uniform over the cone of directions within theta_max of +z, cos_max = cos(theta_max):
// z uniform in [cos_max, 1]. From a sphere's centre these directions pick points
// uniformly over a spherical cap, by area: how a sphere light samples the part of
// itself a point can see.
inline vec3 sample_uniform_cone(vec2 u, double cos_max) {
  const double z = 1 - u.x * (1 - cos_max), r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
// Solid angle: 1 / (2 pi (1 - cos_max)) inside the cone.
inline double uniform_cone_pdf(double cos_max) { return 1 / (2 * pi * (1 - cos_max)); }
inline vec2 invert_uniform_cone_sample(const vec3& w, double cos_max) {
  const double phi = std::atan2(w.y, w.x);
  return {(1 - w.z) / (1 - cos_max), (phi < 0 ? phi + 2 * pi : phi) / (2 * pi)};
}

// A Phong lobe of exponent n around +z: density proportional to cos^n(alpha), alpha the
// angle from +z. Its cumulative in z = cos(alpha) is z^(n + 1), so z = u.x^(1 / (n + 1)),
// phi = 2 pi u.y. Large n squeezes the lobe towards +z (a sharp reflection).
inline vec3 sample_phong_lobe(vec2 u, double n) {
  const double z = std::pow(u.x, 1 / (n + 1)), r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
// Solid angle: p(w) = (n + 1) / (2 pi) cos^n(alpha) for cos(alpha) = w.z > 0, else 0.
inline double phong_lobe_pdf(double cos_alpha, double n) {
  return cos_alpha > 0 ? (n + 1) / (2 * pi) * std::pow(cos_alpha, n) : 0.0;
}
inline vec2 invert_phong_lobe_sample(const vec3& w, double n) {
  const double phi = std::atan2(w.y, w.x);
  return {std::pow(w.z, n + 1), (phi < 0 ? phi + 2 * pi : phi) / (2 * pi)};
}

// Uniform over a triangle, as barycentric coordinates (b0, b1, b2) of its corners:
// b0 = 1 - sqrt(u.x), b1 = u.y sqrt(u.x). The square root undoes the triangle's
// narrowing towards corner 0, so equal areas get equal shares.
inline vec3 sample_uniform_triangle(vec2 u) {
  const double s = std::sqrt(u.x);
  return {1 - s, u.y * s, (1 - u.y) * s};
}
// Area: 1 / A over the triangle.
inline double uniform_triangle_pdf(double area) { return 1 / area; }
inline vec2 invert_uniform_triangle_sample(const vec3& b) {
  const double s = 1 - b.x;
  return {s * s, s > 0 ? b.y / s : 0.0};
}

// A density per unit area at a point y of a light, seen from x, as a density per
// steradian of the direction from x to y: a patch dA at distance d, tilted by theta_y
// from the direction, covers dw = |cos(theta_y)| dA / d^2 of x's sky, so
//   p_w = p_A d^2 / |cos(theta_y)|.
// Infinite for a light seen exactly edge-on (it covers no solid angle there).
inline double area_to_solid_angle(double pdf_area, double distance_squared, double cos_at_light) {
  return pdf_area * distance_squared / std::abs(cos_at_light);
}

// Multiple importance sampling (Veach's power heuristic, beta = 2): the weight of a
// sample drawn n_f times from density p_f when n_g samples also come from p_g:
//   w_f = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2).
// The weights of the two strategies add up to 1 wherever either can sample. Returns 0
// when the weight is not a finite number (both densities 0, or one infinite).
inline double power_heuristic(int n_f, double p_f, int n_g, double p_g) {
  // BEGIN EXERCISE 14.5 the power heuristic
  const double f = n_f * p_f, g = n_g * p_g;
  const double w = f * f / (f * f + g * g);
  return std::isfinite(w) ? w : 0.0;
  // END EXERCISE 14.5
}

// A choice among n things with probabilities proportional to weights (lights by
// their power): the cumulative sums, searched with one uniform number.
struct DiscreteDistribution {
  std::vector<double> cdf;  // cdf[i] = (w_0 + ... + w_i) / total; cdf.back() = 1
};
// Throws std::invalid_argument for no weights, a negative or non-finite weight, or all zero.
DiscreteDistribution make_discrete_distribution(const std::vector<double>& weights);
int sample_discrete(const DiscreteDistribution& distribution, double u);
// Probability of choosing i: w_i / total.
double discrete_pdf(const DiscreteDistribution& distribution, int i);

}  // namespace gi
