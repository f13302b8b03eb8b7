#pragma once
#include "gi/core/ray.hpp"
#include "gi/scene/light.hpp"
#include "gi/scene/material.hpp"
#include "gi/accel/world.hpp"

namespace gi {

// The Phong model's contribution of one light at a surface point:
//   I_l [k_d max(0, N.L) + k_s max(0, R.V)^n],   R = reflection of L about N,
// with unit vectors N (normal, on the viewer's side), L (to the light), V (to the eye),
// and kd the diffuse colour at the point (after texturing). A light behind the
// surface (N.L <= 0) contributes nothing, highlight included.
Color phong(const Material& material, const Color& kd, const vec3& n, const vec3& l, const vec3& v,
            const Color& light_intensity);

// The shadow ray from a surface point towards a point light: it starts `epsilon`
// off the surface along the unit normal n (on the side the light is, so that it cannot
// hit its own surface through round-off) and ends just short of the light, so that
// only objects between the point and the light count.
Ray shadow_ray(const vec3& point, const vec3& n, const vec3& light_position, double epsilon);

// Is the point lit by this light, i.e. does its shadow ray reach the light?
bool visible(const World& world, const vec3& point, const vec3& n, const vec3& light_position, double epsilon);

}  // namespace gi
