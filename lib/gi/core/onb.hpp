#pragma once
#include "gi/core/math.hpp"

namespace gi {

// An orthonormal basis (u, v, w) around a unit vector w: turns directions sampled
// around +z (hemisphere, cone) into world space. Frisvad's branch-free construction
// as corrected by Duff et al. 2017 ("Building an Orthonormal Basis, Revisited").
struct Onb {
  vec3 u, v, w;

  explicit Onb(const vec3& n) : w(n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    u = vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    v = vec3(b, sign + n.y * n.y * a, -n.y);
  }

  vec3 to_world(const vec3& local) const { return local.x * u + local.y * v + local.z * w; }
  vec3 to_local(const vec3& world) const { return vec3(dot(world, u), dot(world, v), dot(world, w)); }
};

}  // namespace gi
