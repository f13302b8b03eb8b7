#include "gi/scene/scene_intersect.hpp"

namespace gi {

namespace {

// Each hit found shortens the ray, so later primitives only count when nearer.
template <class Primitive>
void closest_in(const std::vector<Primitive>& primitives, Ray& ray, std::optional<Hit>& best) {
  for (const Primitive& primitive : primitives) {
    if (auto hit = intersect(ray, primitive)) {
      ray.t_max = hit->t;
      best = hit;
    }
  }
}

template <class Primitive>
bool any_in(const std::vector<Primitive>& primitives, const Ray& ray) {
  for (const Primitive& primitive : primitives)
    if (intersect(ray, primitive)) return true;
  return false;
}

}  // namespace

std::optional<Hit> closest_hit(const Scene& scene, Ray ray) {
  std::optional<Hit> best;
  closest_in(scene.spheres, ray, best);
  closest_in(scene.planes, ray, best);
  closest_in(scene.quads, ray, best);
  return best;
}

bool any_hit(const Scene& scene, const Ray& ray) {
  return any_in(scene.spheres, ray) || any_in(scene.quads, ray) || any_in(scene.planes, ray);
}

}  // namespace gi
