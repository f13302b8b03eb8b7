#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gi/accel/bvh.hpp"
#include "gi/accel/bvh_fast.hpp"
#include "gi/accel/traversal_counts.hpp"
#include "gi/geometry/packed_spheres.hpp"
#include "gi/scene/scene_scale.hpp"

namespace gi {

// The lecture's three ways to find what a ray hits, fastest last:
//   BruteForce     test the ray against every primitive: N tests per ray (the spheres
//                  two at a time, packed_spheres.hpp)
//   BoundingBoxes  a box around each object, tested first; the object itself only
//                  when its box is hit. Still N tests, but a box test is cheaper than
//                  most objects' own
//   Bvh            boxes around boxes (bvh.hpp): about log N tests per ray
//   FastBvh        the same boxes made an 8-wide tree (bvh_collapse.hpp), walked by the
//                  production path (bvh_fast.hpp): float slab tests four at once
// All four find the same hits.
enum class Acceleration { BruteForce, BoundingBoxes, Bvh, FastBvh };

std::string name(Acceleration acceleration);  // "brute-force", "bounding-boxes", "bvh", "bvh-fast"
std::vector<std::string> acceleration_names();
// Throws std::invalid_argument, listing the names, when `name` is not one of them.
Acceleration acceleration_from_name(const std::string& name);

// What the ray tracer casts its rays into: a scene and the structure that speeds up
// its ray queries. Planes are unbounded, so every method tests them one by one.
struct World {
  Scene scene;
  Acceleration acceleration = Acceleration::Bvh;
  Bvh bvh;                  // Acceleration::Bvh only
  FastBvh fast_bvh;         // Acceleration::FastBvh only
  std::vector<Aabb> boxes;  // Acceleration::BoundingBoxes only: the spheres' boxes, then the quads'
  PackedSpheres packed;     // Acceleration::BruteForce only: the spheres, coordinate by coordinate
  double scale = 1;         // scene_scale(scene): what rays leaving a surface are offset relative to
};

// Takes the scene and builds what the acceleration needs: the tree (with `settings`)
// or one box per object; measures its scale. Throws std::invalid_argument for settings
// out of range.
World make_world(Scene scene, Acceleration acceleration = Acceleration::Bvh, const BvhSettings& settings = {});

// The nearest hit with t in [ray.t_min, ray.t_max], or nothing: whatever the
// acceleration, the hit brute force finds, up to which of two
// surfaces at exactly the same t is reported. `counts`, when given, is added to
// (FastBvh counts only the planes' tests: its walk counts nothing).
std::optional<Hit> closest_hit(const World& world, const Ray& ray, TraversalCounts* counts = nullptr);
// The same search on `ray` itself, which each hit shortens: on return ray.t_max is the
// nearest hit's t (closest_hit searches a copy of its ray this way).
std::optional<Hit> closest_hit_in_place(const World& world, Ray& ray, TraversalCounts* counts = nullptr);

// Shadow-ray query: is anything hit with t in [t_min, t_max]? Stops at the first hit.
bool any_hit(const World& world, const Ray& ray, TraversalCounts* counts = nullptr);

}  // namespace gi
