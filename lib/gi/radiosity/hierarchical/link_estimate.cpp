#include "gi/radiosity/hierarchical/link_estimate.hpp"

#include "gi/radiosity/form_factor_formulas.hpp"
#include "gi/radiosity/hierarchical/visibility.hpp"

namespace gi {

namespace {

// The largest height of a corner of q above p's plane (negative: all behind it).
double highest_above(const Polygon& p, const Polygon& q) {
  double highest = -1e300;
  for (const vec3& c : q.corners) highest = std::max(highest, dot(c - p.centre, p.normal));
  return highest;
}

}  // namespace

bool can_exchange(const Polygon& p, const Polygon& q) {
  // "Strictly" with a margin of 1e-9 of the sizes: a neighbour in the same plane is
  // not in front of it, whatever the round-off.
  const double size = std::sqrt(std::max(p.area, q.area));
  return highest_above(p, q) > 1e-9 * size && highest_above(q, p) > 1e-9 * size;
}

Link estimate_link(const FormFactorScene& blockers, const Hierarchy& h, int receiver, int source, int order,
                   int rays_per_side, std::uint64_t seed) {
  const Polygon& p = h.nodes[receiver].shape;
  const Polygon& q = h.nodes[source].shape;
  Link link{receiver, source, form_factor_analytic(p, q, order), form_factor_analytic(q, p, order), 0.0};
  link.visibility = link_visibility(blockers, h, receiver, source, rays_per_side, seed);
  return link;
}

}  // namespace gi
