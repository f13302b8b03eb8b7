#pragma once
#include <cstdint>
#include <vector>

#include "gi/radiosity/form_factors.hpp"
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
  vec3 from, to;  // on the receiver, on the source
};
std::vector<ShadowRay> shadow_rays(const Hierarchy& hierarchy, int receiver, int source, int per_side,
                                   std::uint64_t seed);

// V_pq: the fraction of the link's shadow rays that get through, in [0, 1]. Only rays
// that could carry light count: a ray from a point behind the source's plane, or to a
// point behind the receiver's, is no shadow ray of this link (its form factor leaves
// those parts out already). 0 when no ray could carry light. Throws
// std::invalid_argument for per_side outside [1, 16].
double link_visibility(const FormFactorScene& blockers, const Hierarchy& hierarchy, int receiver, int source,
                       int per_side, std::uint64_t seed);

}  // namespace gi
