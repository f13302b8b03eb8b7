#pragma once
#include <optional>

#include "gi/core/ray.hpp"

namespace gi {

// A triangle a, b, c; its normal is normalize((b - a) x (c - a)), so list the corners
// counter-clockwise seen from the front. Radiosity meshes are cast into as triangles
// (two per quadrilateral element), since their elements need not be parallelograms.
struct Triangle {
  vec3 a, b, c;
  int material;
};

// Throws std::invalid_argument for non-finite corners or a triangle without area.
void check(const Triangle& triangle);

// The hit with t in [ray.t_min, ray.t_max], from either side (the normal is the
// front's), or nothing. Moeller and Trumbore's test: solve o + t d = a + u (b - a)
// + v (c - a) by Cramer's rule, u, v >= 0 and u + v <= 1.
std::optional<Hit> intersect(const Ray& ray, const Triangle& triangle);

}  // namespace gi
