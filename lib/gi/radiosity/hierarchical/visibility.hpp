#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// The shadow rays of a link, n x n of them: ray k starts at a point jittered in cell k
// of the receiver's n x n grid (in its parameter square) and ends at a point jittered
// in cell perm(k) of the source's, perm a random permutation. Every end is uniform over
// its node, so the fraction that gets through is an unbiased estimate of the mean
// visibility between the two; fixed points at the cells' centres are not (they read
// a shadow edge the same wrong way on every node along it, 3% of the Cornell box
// floor's direct light at n = 4).
//
// The random numbers come from stream fnv1a(the two nodes' places in their quadtrees)
// of `seed`: the same rays whatever order the hierarchy was refined in and however
// many threads judged it. Points lie on the surface's plane through lifted_centre
// (polygon.hpp), so a twisted surface never hides its own points. The rays are cast
// against the input surfaces (FormFactorScene of their polygons), not the nodes: what
// may stand in the way does not change as the hierarchy is refined.
struct ShadowRay {
  vec3 from, to;          // on the receiver, on the source
  bool may_start_buried = false;  // the receiver is not wholly open (Node::open): `from` may be buried
  int quarter = 0;        // the quarter of the source `to` lies in (its children's order)
};
std::vector<ShadowRay> shadow_rays(const Hierarchy& hierarchy, int receiver, int source, int per_side,
                                   std::uint64_t seed);

// V_pq: the share of the light between the two that gets through, in [0, 1], and
// how it splits over the source's quarters. Each ray that could carry light is
// weighed by what it would carry, the kernel of the form factor cos_p cos_q / r^2:
//   V = sum over rays that get through of w / sum over all of w
// (an unweighted fraction counts a far, grazing ray like a near one, and misses how
// the light near a block's foot is seen). Only rays that could carry light count: a
// ray from a point behind the source's plane, or to a point behind the receiver's, is
// no shadow ray of this link (its form factor leaves those parts out already), and a
// ray from a buried part of the receiver is none either (V is the open part's:
// push-pull hands the light to the open part only; a ray that gets through starts in
// the open, so only a stopped ray from a receiver not wholly open is checked). A ray to a buried part of the
// source counts, and is blocked: B is the open part's. V = 0 when no ray could carry
// light. Throws std::invalid_argument for per_side outside [1, 16].
struct LinkVisibility {
  double V = 0;
  std::array<double, 4> by_quarter{};  // the share that gets through into each quarter of the source; they add up to V
};
LinkVisibility link_visibility(const FormFactorScene& blockers, const Hierarchy& hierarchy, int receiver, int source,
                               int per_side, std::uint64_t seed);

}  // namespace gi
