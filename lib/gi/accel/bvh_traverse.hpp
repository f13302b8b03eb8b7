#pragma once
#include <optional>

#include "gi/accel/bvh.hpp"
#include "gi/accel/traversal_counts.hpp"

namespace gi {

// The ray against the primitive a tree reference names; the hit says which one.
inline std::optional<Hit> intersect(const Ray& ray, const Scene& scene, PrimitiveRef ref) {
  const auto i = static_cast<std::size_t>(ref.index);
  std::optional<Hit> hit;
  switch (ref.kind) {
    case PrimitiveKind::Sphere: hit = intersect(ray, scene.spheres[i]); break;
    case PrimitiveKind::Quad: hit = intersect(ray, scene.quads[i]); break;
    case PrimitiveKind::Triangle: hit = intersect(ray, scene.triangles[i]); break;
  }
  if (hit) hit->object = ref.index;
  return hit;
}

// Ray queries against a tree built over `scene` (its spheres and quads; the World
// adds the planes). Both add to `counts`: a node visited is one whose children's
// boxes or whose primitives are tested, a box test is one call of slab_test, a
// primitive test one call of intersect.

// The nearest hit among the tree's primitives with t in [ray.t_min, ray.t_max], or
// nothing. On a hit, ray.t_max is left at the hit's t.
std::optional<Hit> closest_hit(const Bvh& bvh, const Scene& scene, Ray& ray, TraversalCounts& counts);

// Is any of the tree's primitives hit with t in [ray.t_min, ray.t_max]? Stops at the
// first hit found: enough for a shadow ray.
bool any_hit(const Bvh& bvh, const Scene& scene, const Ray& ray, TraversalCounts& counts);

}  // namespace gi
