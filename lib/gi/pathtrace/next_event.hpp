#pragma once
#include "gi/pathtrace/bsdf.hpp"
#include "gi/pathtrace/lights.hpp"

namespace gi {

// Next-event estimation: the light reflected at x towards wo, estimated from one point
// y on a light. The reflection integral is over directions,
//   L_r(x, wo) = int f(wo, wi) L_e(y(wi)) |cos theta_x| dw_i,
// but y was drawn with a density per unit area p_A, so the direction wi = (y - x) / |y - x|
// has the density per steradian
//   p_light = p_A |y - x|^2 / cos theta_y,     cos theta_y = n_y . (x - y) / |x - y|,
// and one sample estimates L_r by
//   f(wo, wi) L_e(y) |cos theta_x| / p_light
//   = f(wo, wi) L_e(y) |cos theta_x| cos theta_y / (p_A |y - x|^2).
// A light that turns its back on x (cos theta_y <= 0) gives nothing.
struct DirectSample {
  vec3 wi;          // unit, from x towards y
  double distance;  // |y - x|
  double p_light;   // density of wi per steradian; 0 when y faces away from x
  Color estimate;   // f L_e |cos theta_x| / p_light; visibility and the MIS weight are the caller's
};

// n is the surface's unit normal at x (either side), wo the unit direction to the viewer.
DirectSample next_event_estimate(const Bsdf& bsdf, const vec3& x, const vec3& n, const vec3& wo, const LightSample& y);

}  // namespace gi
