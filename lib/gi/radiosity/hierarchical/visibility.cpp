#include "gi/radiosity/hierarchical/visibility.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "gi/core/hash.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"
#include "gi/radiosity/form_factors/shaft.hpp"

namespace gi {

namespace {

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
    rays[k] = {lifted_point(h, h.nodes[receiver], u, v), lifted_point(h, h.nodes[source], s, t),
               h.nodes[receiver].open != 0xFFFF, (s >= 0.5 ? 1 : 0) + (t >= 0.5 ? 2 : 0)};
  }
  return rays;
}

LinkVisibility link_visibility(const FormFactorScene& blockers, const Hierarchy& h, int receiver, int source, int n,
                               std::uint64_t seed) {
  const std::vector<ShadowRay> rays = shadow_rays(h, receiver, source, n, seed);
  // Only what stands between the two can block their rays (shaft.hpp; between two walls
  // of a room, nothing at all). Every ray ends inside the outline of the nodes' lifted
  // corners, so the shaft around those eight points holds every ray.
  std::vector<vec3> corners;
  for (const int node : {receiver, source})
    for (const auto& [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
      corners.push_back(lifted_point(h, h.nodes[node], u, v));
  const Shaft shaft(blockers, corners);
  // What exercise 13.2 reads (a kit's stub in its place reads none of them).
  [[maybe_unused]] const vec3& n_p = h.nodes[receiver].shape.normal;
  [[maybe_unused]] const vec3& n_q = h.nodes[source].shape.normal;
  [[maybe_unused]] const double size = std::sqrt(h.total_area);  // buried's scale
  // BEGIN EXERCISE 13.2 the visibility of a link
  LinkVisibility seen;
  double carrying = 0, through = 0;
  for (const ShadowRay& ray : rays) {
    const vec3 d = ray.to - ray.from;
    const double cos_p = dot(d, n_p), cos_q = -dot(d, n_q);  // times |d| each
    if (cos_p <= 0 || cos_q <= 0) continue;                   // carries no light
    const bool gets_through = shaft.visible(ray.from, ray.to);
    if (!gets_through && ray.may_start_buried && buried(blockers, ray.from, n_p, size)) continue;  // no light there
    const double w = cos_p * cos_q / (dot(d, d) * dot(d, d));  // cos_p cos_q / r^2
    carrying += w;
    if (gets_through) through += w, seen.by_quarter[ray.quarter] += w;
  }
  if (carrying > 0) {
    seen.V = through / carrying;  // exactly 1 when every ray gets through: no shadow edge inside
    for (double& share : seen.by_quarter) share /= carrying;
  }
  return seen;
  // END EXERCISE 13.2
}

}  // namespace gi
