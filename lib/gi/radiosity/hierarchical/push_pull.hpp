#pragma once
#include <vector>

#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// One step of the hierarchical solve is a gather over every link, then a push-pull
// over every quadtree (Hanrahan, Salzman and Aupperle 1991).

// Gathering: what a node's links bring in, reflected,
//   gathered_p = rho_p * sum over its links l of F_l V_l sent_source(l)
// per colour channel; `sent` holds what every node sends (node index -> Node::sent: its
// B, or the leaves' B times their send_scale where the links are balanced, pulled up as
// open-area means; hierarchical_solver.cpp fills it before every gather). A
// source that has children sends each quarter's share of V by that quarter's own,
//   F_l * sum over c of V_l,c sent_child c        (Link::by_quarter)
// so that a link whose light comes mostly from the source's bright or near part
// carries that part's B, not the whole source's mean: with the mean alone, the walls
// and ceiling of the Cornell box gathered 0.5-1.7% less than the leaves' own B field
// sends them (measured by Monte Carlo from the leaves, docs/13).
Color gather(const Hierarchy& hierarchy, const Node& receiver, const std::vector<Color>& sent);

// Push-pull over the subtree of `node`. A node's gathered light lands on all of it,
// so it is pushed down and added to every leaf below, with what its ancestors
// gathered (`pushed`); a leaf's radiosity is its source term (E, or D with exact
// direct light) plus all of that, times its gather_scale (balance.hpp; 1 until the
// links are balanced):
//   B_leaf = source_leaf + gather_scale * (pushed + gathered_leaf)
// and radiosity is pulled back up as the area-weighted mean of the children,
//   B_p = sum_c A_c B_c / sum_c A_c
// so that every node holds the mean over its area. A_c is the child's open area
// (Node::open_area): a part buried inside a solid, such as the floor under a block,
// sends no light and must not dim the mean. Sets B of every node of the subtree and
// returns B_node.
Color push_pull(Hierarchy& hierarchy, int node, const Color& pushed);

}  // namespace gi
