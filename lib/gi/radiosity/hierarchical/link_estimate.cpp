#include "gi/radiosity/hierarchical/link_estimate.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"
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

Link estimate_form_factors(const Hierarchy& h, int receiver, int source, int order) {
  const Polygon& p = h.nodes[receiver].shape;
  const Polygon& q = h.nodes[source].shape;
  // F_pq over the receiver's open part: a buried point sees the back of the solid it is
  // in (F = 0 to its faces), and counting it dimmed a floor node at a block's foot by its
  // buried share. (Wholly open: over all of it, as Gauss's rule has it.)
  const Node& node = h.nodes[receiver];
  const auto open = [&](double s, double t) { return open_at(node, s, t); };
  // Gauss points lie inside; F changes most where the receiver comes nearest the
  // source (beside a neighbour's edge it rises to 1/2). So the spread also looks at the
  // corners, and at the receiver's points nearest the source's corners and centre
  // (their feet on its plane, clamped into it): a block's face meets the floor along
  // its bottom edge, where F to the floor in front peaks between the corners, and a
  // link judged by its inner points alone handed a face's foot a hundredth of its view
  // of the floor there (the blocks came out dark, docs/13). Points set in by
  // corner_inset of the receiver's size, where F is finite.
  std::array<vec2, 9> look_at;  // on the stack: a link is judged a million times
  std::size_t looks = 0;
  const auto look = [&](vec2 st) {
    st = glm::clamp(st, corner_inset, 1 - corner_inset);
    // A far source's feet all clamp to the receiver's corners and edges: each point once.
    if (std::find(look_at.begin(), look_at.begin() + looks, st) == look_at.begin() + looks) look_at[looks++] = st;
  };
  for (const double u : {0.0, 1.0})
    for (const double v : {0.0, 1.0}) look({u, v});
  for (const vec3& c : {q.corners[0], q.corners[1], q.corners[2], q.corners[3], q.centre})
    look(unbilinear(p.corners, p.normal, c - dot(c - p.centre, p.normal) * p.normal));
  const FormFactorRange F = analytic_range_unchecked(
      p, q, order, node.open == 0xFFFF ? std::function<bool(double, double)>{} : open,
      std::span<const vec2>(look_at.data(), looks));
  Link link{receiver, source, F.mean, F.mean * p.area / q.area, 0.0};  // F_qp by reciprocity: A_p F_pq = A_q F_qp
  link.F_min = static_cast<float>(F.least), link.F_max = static_cast<float>(F.greatest);
  return link;
}

void estimate_visibility(Link& link, const FormFactorScene& blockers, const Hierarchy& h, int rays_per_side,
                         std::uint64_t seed) {
  const LinkVisibility seen = link_visibility(blockers, h, link.receiver, link.source, rays_per_side, seed);
  link.visibility = seen.V;
  for (int c = 0; c < 4; ++c) link.by_quarter[c] = static_cast<float>(seen.by_quarter[c]);
}

Link estimate_link(const FormFactorScene& blockers, const Hierarchy& h, int receiver, int source, int order,
                   int rays_per_side, std::uint64_t seed) {
  Link link = estimate_form_factors(h, receiver, source, order);
  estimate_visibility(link, blockers, h, rays_per_side, seed);
  return link;
}

}  // namespace gi
