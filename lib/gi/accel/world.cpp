#include "gi/accel/world.hpp"

#include <stdexcept>
#include <utility>

#include "gi/accel/bvh_traverse.hpp"

namespace gi {

namespace {

// Brute force over one kind of primitive. Each hit shortens the ray, so later
// primitives only count when nearer.
template <class Primitive>
void closest_in(const std::vector<Primitive>& primitives, Ray& ray, std::optional<Hit>& nearest,
                TraversalCounts& counts) {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    ++counts.primitive_tests;
    if (auto hit = intersect(ray, primitives[i])) {
      ray.t_max = hit->t;
      nearest = hit;
      nearest->object = static_cast<int>(i);
    }
  }
}

template <class Primitive>
bool any_in(const std::vector<Primitive>& primitives, const Ray& ray, TraversalCounts& counts) {
  for (const Primitive& primitive : primitives) {
    ++counts.primitive_tests;
    if (intersect(ray, primitive)) return true;
  }
  return false;
}

// A bounding box per object: the slab test first, the object only when its box is hit.
template <class Primitive>
void closest_in_boxes(const std::vector<Primitive>& primitives, const Aabb* boxes, Ray& ray, const vec3& inv_dir,
                      std::optional<Hit>& nearest, TraversalCounts& counts) {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    ++counts.box_tests;
    if (!slab_test(ray, inv_dir, boxes[i])) continue;
    ++counts.primitive_tests;
    if (auto hit = intersect(ray, primitives[i])) {
      ray.t_max = hit->t;
      nearest = hit;
      nearest->object = static_cast<int>(i);
    }
  }
}

template <class Primitive>
bool any_in_boxes(const std::vector<Primitive>& primitives, const Aabb* boxes, const Ray& ray, const vec3& inv_dir,
                  TraversalCounts& counts) {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    ++counts.box_tests;
    if (!slab_test(ray, inv_dir, boxes[i])) continue;
    ++counts.primitive_tests;
    if (intersect(ray, primitives[i])) return true;
  }
  return false;
}

}  // namespace

std::string name(Acceleration acceleration) {
  switch (acceleration) {
    case Acceleration::BruteForce: return "brute-force";
    case Acceleration::BoundingBoxes: return "bounding-boxes";
    case Acceleration::Bvh: return "bvh";
    case Acceleration::FastBvh: return "bvh-fast";
  }
  throw std::invalid_argument("unknown acceleration");
}

std::vector<std::string> acceleration_names() {
  return {name(Acceleration::BruteForce), name(Acceleration::BoundingBoxes), name(Acceleration::Bvh),
          name(Acceleration::FastBvh)};
}

Acceleration acceleration_from_name(const std::string& text) {
  for (Acceleration a : {Acceleration::BruteForce, Acceleration::BoundingBoxes, Acceleration::Bvh, Acceleration::FastBvh})
    if (name(a) == text) return a;
  throw std::invalid_argument("unknown acceleration '" + text + "' (known: brute-force, bounding-boxes, bvh, bvh-fast)");
}

World make_world(Scene scene, Acceleration acceleration, const BvhSettings& settings) {
  World world{std::move(scene), acceleration, {}, {}, {}, {}};
  world.scale = scene_scale(world.scene);
  if (acceleration == Acceleration::BruteForce) world.packed = pack(world.scene.spheres);
  if (acceleration == Acceleration::Bvh) world.bvh = build_bvh(world.scene, settings);
  if (acceleration == Acceleration::FastBvh) {
    // The SAH collapse picks the leaves itself, from a binary tree cut down to one
    // primitive a leaf; the largest-first collapse keeps the binary tree's leaves.
    BvhSettings binary = settings;
    if (settings.collapse == WideCollapse::Sah) binary.max_leaf_size = 1;
    world.fast_bvh = make_fast_bvh(build_bvh(world.scene, binary), world.scene, settings);
  }
  if (acceleration == Acceleration::BoundingBoxes) {
    world.boxes.reserve(world.scene.spheres.size() + world.scene.quads.size() + world.scene.triangles.size());
    for (const Sphere& sphere : world.scene.spheres) world.boxes.push_back(bounds(sphere));
    for (const Quad& quad : world.scene.quads) world.boxes.push_back(bounds(quad));
    for (const Triangle& triangle : world.scene.triangles) world.boxes.push_back(bounds(triangle));
  }
  return world;
}

std::optional<Hit> closest_hit(const World& world, const Ray& query, TraversalCounts* counts) {
  Ray ray = query;  // each hit shortens this copy
  return closest_hit_in_place(world, ray, counts);
}

// The counts go to a local first: with counts == nullptr that costs a few register
// increments per ray, and no branch in the inner loops.
std::optional<Hit> closest_hit_in_place(const World& world, Ray& ray, TraversalCounts* counts) {
  const Scene& scene = world.scene;
  TraversalCounts local;
  std::optional<Hit> nearest;
  switch (world.acceleration) {
    case Acceleration::BruteForce:
      closest_sphere(world.packed, scene.spheres, ray, nearest);
      local.primitive_tests += scene.spheres.size();  // every sphere is tested, four at a time
      closest_in(scene.quads, ray, nearest, local);
      closest_in(scene.triangles, ray, nearest, local);
      break;
    case Acceleration::BoundingBoxes: {
      const vec3 inv_dir = 1.0 / ray.direction;
      closest_in_boxes(scene.spheres, world.boxes.data(), ray, inv_dir, nearest, local);
      closest_in_boxes(scene.quads, world.boxes.data() + scene.spheres.size(), ray, inv_dir, nearest, local);
      closest_in_boxes(scene.triangles, world.boxes.data() + scene.spheres.size() + scene.quads.size(), ray, inv_dir,
                       nearest, local);
      break;
    }
    case Acceleration::Bvh:
      nearest = closest_hit(world.bvh, scene, ray, local);  // leaves ray.t_max at its hit
      break;
    case Acceleration::FastBvh:
      nearest = closest_hit(world.fast_bvh, scene, ray);  // leaves ray.t_max at its hit
      break;
  }
  closest_in(scene.planes, ray, nearest, local);
  if (counts) *counts += local;
  return nearest;
}

bool any_hit(const World& world, const Ray& ray, TraversalCounts* counts) {
  const Scene& scene = world.scene;
  TraversalCounts local;
  bool hit = false;
  switch (world.acceleration) {
    case Acceleration::BruteForce: {
      const int blocker = any_sphere(world.packed, scene.spheres, ray);
      // Counted as the plain loop counts: up to and including the first sphere hit.
      local.primitive_tests += blocker >= 0 ? blocker + 1 : scene.spheres.size();
      hit = blocker >= 0 || any_in(scene.quads, ray, local) || any_in(scene.triangles, ray, local);
      break;
    }
    case Acceleration::BoundingBoxes: {
      const vec3 inv_dir = 1.0 / ray.direction;
      hit = any_in_boxes(scene.spheres, world.boxes.data(), ray, inv_dir, local) ||
            any_in_boxes(scene.quads, world.boxes.data() + scene.spheres.size(), ray, inv_dir, local) ||
            any_in_boxes(scene.triangles, world.boxes.data() + scene.spheres.size() + scene.quads.size(), ray,
                         inv_dir, local);
      break;
    }
    case Acceleration::Bvh:
      hit = any_hit(world.bvh, scene, ray, local);
      break;
    case Acceleration::FastBvh:
      hit = any_hit(world.fast_bvh, scene, ray);
      break;
  }
  hit = hit || any_in(scene.planes, ray, local);
  if (counts) *counts += local;
  return hit;
}

}  // namespace gi
