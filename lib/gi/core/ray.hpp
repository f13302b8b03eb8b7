#pragma once
#include "gi/core/math.hpp"

namespace gi {

// A ray is the half-line origin + t * direction for t in [t_min, t_max].
// A ray that leaves a surface must not hit that same surface again through
// round-off ("shadow acne"): the tracer starts such rays a small epsilon off the
// surface. t_max stops a shadow ray at its light.
struct Ray {
  vec3 origin;
  vec3 direction;  // unit length wherever the tracer makes a ray
  double t_min = 0;
  double t_max = std::numeric_limits<double>::infinity();

  vec3 at(double t) const { return origin + t * direction; }
};

// What a ray hit: the distance along the ray, the point, the surface's outward
// unit normal there, the index of the surface's material in the Scene, and which
// primitive it was: its index in the Scene's vector of its kind (set by the ray
// queries of gi/accel/world.hpp; radiosity uses it to find the element hit).
struct Hit {
  double t;
  vec3 point;
  vec3 normal;
  int material;
  int object = -1;
};

}  // namespace gi
