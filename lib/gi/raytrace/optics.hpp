#pragma once
#include <optional>

#include "gi/core/math.hpp"

namespace gi {

// Mirror direction of the incoming direction d about the unit normal n:
//   r = d - 2 (d.n) n          (d points towards the surface; so does n's side)
vec3 reflect(const vec3& d, const vec3& n);

// Snell's law, eta_i sin(theta_i) = eta_t sin(theta_t), as a direction:
// d is the unit incoming direction, n the unit normal on the side d comes from
// (d.n < 0), and eta = eta_i / eta_t the ratio of the indices (from / into).
// Returns the unit transmitted direction, or nothing under total internal
// reflection (sin(theta_t) would exceed 1).
std::optional<vec3> refract(const vec3& d, const vec3& n, double eta);

// Fraction of light reflected at a smooth dielectric boundary, unpolarised: the
// mean of the s- and p-polarised Fresnel equations. cos_i is the cosine of the
// angle of incidence (>= 0) on the side of index eta_i. Returns 1 under total
// internal reflection.
double fresnel_dielectric(double cos_i, double eta_i, double eta_t);

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5, F0 = ((eta_i - eta_t)/(eta_i + eta_t))^2,
// with cos taken on the denser side so that it agrees with total internal reflection.
double fresnel_schlick(double cos_i, double eta_i, double eta_t);

}  // namespace gi
