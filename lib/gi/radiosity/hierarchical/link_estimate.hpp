#pragma once
#include <cstdint>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// Can any light pass between the two polygons? Only if each has a corner strictly in
// front of the other's plane: otherwise one lies wholly behind the other (or both in
// one plane), and every form factor between their points is 0.
bool can_exchange(const Polygon& p, const Polygon& q);

// The link that would bring q's light to p, with its numbers:
//   F       F_pq, the library's analytic point-to-polygon factor (Lambert's contour
//           integral, form_factor_formulas.hpp) averaged over `order` x `order`
//           Gauss-Legendre points of the receiver (order 1 is its centre, as in
//           Hanrahan et al.); nothing in between
//   F_min, F_max  the least and greatest F over those points, p's four corners and
//           the points of p nearest q's corners and centre (set in by corner_inset):
//           how F changes across p
//   F_back  F_qp = F_pq A_p / A_q, by reciprocity
//   V       link_visibility with `rays_per_side`^2 shadow rays from `seed` (visibility.hpp)
// The light it carries is F V: exact where F is constant over the receiver and V is
// all or nothing, and the oracle's business everywhere else.
inline constexpr double corner_inset = 1e-4;
Link estimate_link(const FormFactorScene& blockers, const Hierarchy& hierarchy, int receiver, int source, int order,
                   int rays_per_side, std::uint64_t seed);

// The same in two steps: the form factors alone (F, F_back, F_min, F_max; V left at 0),
// which is all the oracle needs where it would split the same end with or without a
// shadow edge inside; then V and its quarters' shares, for a link that may be kept.
Link estimate_form_factors(const Hierarchy& hierarchy, int receiver, int source, int order);
void estimate_visibility(Link& link, const FormFactorScene& blockers, const Hierarchy& hierarchy, int rays_per_side,
                         std::uint64_t seed);

}  // namespace gi
