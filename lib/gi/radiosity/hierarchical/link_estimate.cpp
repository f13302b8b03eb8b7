#include "gi/radiosity/hierarchical/link_estimate.hpp"

#include <algorithm>

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
  FormFactorRange F = form_factor_analytic_range(p, q, order);
  // Gauss points lie inside; F changes most towards the corners (beside a neighbour's
  // edge it rises to 1/2). So the spread also looks at the corners, set in by
  // corner_inset of the receiver's size, where F is finite.
  for (const double u : {corner_inset, 1 - corner_inset})
    for (const double v : {corner_inset, 1 - corner_inset}) {
      const double at = form_factor_point_to_polygon(bilinear(p.corners, u, v), p.normal, q);
      F.least = std::min(F.least, at), F.greatest = std::max(F.greatest, at);
    }
  Link link{receiver, source, F.mean, F.mean * p.area / q.area, 0.0};  // F_qp by reciprocity: A_p F_pq = A_q F_qp
  link.F_min = static_cast<float>(F.least), link.F_max = static_cast<float>(F.greatest);
  link.visibility = link_visibility(blockers, h, receiver, source, rays_per_side, seed);
  return link;
}

}  // namespace gi
