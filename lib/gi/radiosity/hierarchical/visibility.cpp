#include "gi/radiosity/hierarchical/visibility.hpp"

#include <numeric>
#include <stdexcept>

#include "gi/core/hash.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/rng.hpp"

namespace gi {

namespace {

// The point (u, v) of a node, moved along its surface's normal onto the plane through
// the surface's lifted centre (a no-op on a flat surface).
vec3 lifted_point(const Hierarchy& h, const Node& node, double u, double v) {
  const vec3 p = node_point(h, node, u, v);
  const Polygon& surface = h.nodes[node.surface].shape;  // the root: the whole surface
  return p + (lift(surface) - dot(p - surface.centre, surface.normal)) * surface.normal;
}

std::uint64_t place(const Hierarchy& h, int receiver, int source) {
  const Node &p = h.nodes[receiver], &q = h.nodes[source];
  const int key[8] = {p.surface, p.level, p.i, p.j, q.surface, q.level, q.i, q.j};
  return fnv1a(std::string_view(reinterpret_cast<const char*>(key), sizeof key));
}

}  // namespace

std::vector<ShadowRay> shadow_rays(const Hierarchy& h, int receiver, int source, int n, std::uint64_t seed) {
  if (n < 1 || n > 16) throw std::invalid_argument("visibility: rays per side must lie in [1, 16]");
  Rng rng(seed, place(h, receiver, source));
  std::vector<int> perm(n * n);
  std::iota(perm.begin(), perm.end(), 0);
  for (int k = n * n - 1; k > 0; --k) std::swap(perm[k], perm[rng.below(k + 1)]);  // Fisher-Yates
  std::vector<ShadowRay> rays(n * n);
  for (int k = 0; k < n * n; ++k) {
    const double u = (k % n + rng.uniform()) / n, v = (k / n + rng.uniform()) / n;
    const double s = (perm[k] % n + rng.uniform()) / n, t = (perm[k] / n + rng.uniform()) / n;
    rays[k] = {lifted_point(h, h.nodes[receiver], u, v), lifted_point(h, h.nodes[source], s, t)};
  }
  return rays;
}

double link_visibility(const FormFactorScene& blockers, const Hierarchy& h, int receiver, int source, int n,
                       std::uint64_t seed) {
  const std::vector<ShadowRay> rays = shadow_rays(h, receiver, source, n, seed);
  const vec3& n_p = h.nodes[receiver].shape.normal;
  const vec3& n_q = h.nodes[source].shape.normal;
  // BEGIN EXERCISE 13.2 the visibility of a link
  int carrying = 0, through = 0;
  for (const ShadowRay& ray : rays) {
    if (dot(ray.to - ray.from, n_p) <= 0 || dot(ray.from - ray.to, n_q) <= 0) continue;  // carries no light
    ++carrying;
    if (blockers.visible(ray.from, ray.to)) ++through;
  }
  return carrying > 0 ? static_cast<double>(through) / carrying : 0.0;
  // END EXERCISE 13.2
}

}  // namespace gi
