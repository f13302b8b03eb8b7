#pragma once
#include <optional>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/form_factors/shaft.hpp"
#include "gi/radiosity/hierarchical/leaf_mesh.hpp"

namespace gi {

// The final gather: the light that has bounced, gathered at a point x of a leaf over
// the links of the leaf and of its ancestors -- the links the leaf's B came through --
// with each link's F taken at x instead of once for its whole receiver (Lischinski,
// Tampieri and Greenberg 1993 gather over the links so at the end of their solution):
//   gathered(x) = rho sum over links l of  light_l F(x -> q_l) / F_l
// light_l = F_l V_l B_q, what the link hands its receiver (push_pull.hpp's gather, by
// the source's quarters where it has children), F_l its F (the mean over the receiver)
// and F(x -> q_l) the exact point-to-polygon factor (form_factor_formulas.hpp). A link
// spreads its light evenly over its receiver; here the light follows F, rising towards
// a crease where the receiver meets its source as it does in the scene, however large
// the receiver. B is the solution's; F, and for a partly hidden link V (below), are x's.
//
// A link whose F changes little over its receiver (F_max <= near_spread F_min) is
// taken as it is: F(x) / F_l is then within its spread of 1, and its light counts once
// per node, not once per point.
inline constexpr double near_spread = 1.5;

// Unless a shadow's edge lies inside it (0 < V < 1): its one V spreads the light that
// gets through evenly over the receiver, where from some points the source is wholly
// hidden and from others wholly seen. Such a link is read at x with its visibility
// taken again from x (light_at): by gather_rays_per_side^2 rays from x to the centres
// of as many cells of the source. Against the path-traced Cornell box this halved the
// error left at a loose threshold (docs/13): the shadows the indirect light casts, at
// the blocks' feet, are sharper than the links that carry it.
inline constexpr int gather_rays_per_side = 2;

// light_l = F_l V_l B_q: what link l hands its receiver, before rho (push_pull.hpp's
// gather, by the source's quarters where it has children), with the sources' own B --
// the solution -- not what balanced links send (balance.hpp): the gather takes F at the
// point, so the sums the balance mends are not the ones it reads.
Color link_light(const Hierarchy& hierarchy, const Link& link);

class LinkGather {
 public:
  explicit LinkGather(const Hierarchy& hierarchy);
  Color at(int leaf, const vec3& x) const;  // gathered(x) for a point x of leaf `leaf`

  // light_l as x sees it: link_light, but for a link with a shadow's edge inside,
  // F_l times the B of the source's quarters that x's rays reach, each ray weighed by
  // the kernel cos cos / r^2 as link_visibility weighs its own (visibility.hpp). A
  // point buried in a solid sees nothing: there the link's own V stands (the point is
  // never seen, but its value is shaded into the open part of its leaf).
  Color light_at(const Link& link, int leaf, const vec3& x) const;  // link: one of the hierarchy's

 private:
  const Hierarchy* hierarchy_;
  FormFactorScene blockers_;             // the input surfaces, as the links' shadow rays see them
  std::vector<Color> far_;               // per node: the light of its far links, summed
  std::vector<std::vector<int>> near_;   // per node: its near links (indices into Node::links)
  // Per node, per link (Node::links' order): for a near link with a shadow's edge inside,
  // the shaft between its two nodes (shaft.hpp). light_at's rays then test the few
  // surfaces in between, with the same answers as the whole scene's (a twentieth of the
  // run at BF_eps 4e-4).
  std::vector<std::vector<std::optional<Shaft>>> shafts_;
};

// gathered(x) at every vertex of the leaf mesh, for Gouraud shading: each leaf gathers
// at its corners, set in by gather_inset of its size (at a crease itself F to the
// neighbour is its peak, and a line to the next vertex through it lit the whole leaf
// by the crease's light), a vertex takes the area-weighted mean of its leaves' values
// (each leaf has its own links), and a T-vertex the value its edge has there
// (leaf_mesh.hpp's cure for cracks). Same values for any thread count.
inline constexpr double gather_inset = 0.05;
std::vector<Color> gathered_at_vertices(const Hierarchy& hierarchy, const LeafMesh& leaves, int threads);

}  // namespace gi
