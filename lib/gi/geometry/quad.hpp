#pragma once
#include <array>
#include <optional>

#include "gi/core/ray.hpp"

namespace gi {

// A parallelogram: corner + s * edge_u + t * edge_v for s, t in [0, 1]. Its normal is
// normalize(edge_u x edge_v): list the edges counter-clockwise seen from the front.
// Walls, boxes, area lights and radiosity patches are all quads.
struct Quad {
  vec3 corner;
  vec3 edge_u;
  vec3 edge_v;
  int material;
};

// Throws std::invalid_argument for non-finite input or edges that span no area.
void check(const Quad& quad);

vec3 normal(const Quad& quad);
double area(const Quad& quad);
vec3 centre(const Quad& quad);

// The six faces of the axis-aligned box [lo, hi], normals pointing out.
std::array<Quad, 6> box_quads(const vec3& lo, const vec3& hi, int material);

// The hit with t in [ray.t_min, ray.t_max] inside the parallelogram, or nothing.
std::optional<Hit> intersect(const Ray& ray, const Quad& quad);

}  // namespace gi
