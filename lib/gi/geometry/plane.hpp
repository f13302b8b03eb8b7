#pragma once
#include <optional>

#include "gi/core/ray.hpp"

namespace gi {

// The infinite plane through `point` with unit `normal`: all x with (x - point).n = 0.
struct Plane {
  vec3 point;
  vec3 normal;
  int material;
};

// Throws std::invalid_argument unless the point is finite and the normal unit length.
void check(const Plane& plane);

// The hit with t in [ray.t_min, ray.t_max], or nothing (also for a ray parallel to
// the plane). The normal returned is the plane's own, whichever side the ray comes from.
std::optional<Hit> intersect(const Ray& ray, const Plane& plane);

}  // namespace gi
