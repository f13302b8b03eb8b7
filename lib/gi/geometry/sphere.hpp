#pragma once
#include <optional>

#include "gi/core/ray.hpp"

namespace gi {

struct Sphere {
  vec3 center;
  double radius;
  int material;
};

// Throws std::invalid_argument unless the centre is finite and the radius positive.
void check(const Sphere& sphere);

// The nearest hit with t in [ray.t_min, ray.t_max], or nothing. The ray's direction
// need not be unit length: t is measured in units of the direction.
std::optional<Hit> intersect(const Ray& ray, const Sphere& sphere);

}  // namespace gi
