#pragma once
#include <vector>

#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// One step of the hierarchical solve is a gather over every link, then a push-pull
// over every quadtree (Hanrahan, Salzman and Aupperle 1991).

// Gathering: what a node's links bring in, reflected,
//   gathered_p = rho_p * sum over its links l of F_l V_l B_source(l)
// per colour channel; `B` holds every node's radiosity (node index -> B).
Color gather(const Node& receiver, const std::vector<Color>& B);

// Push-pull over the subtree of `node`. A node's gathered light lands on all of it,
// so it is pushed down and added to every leaf below, with what its ancestors
// gathered (`pushed`); a leaf's radiosity is its emission plus all of that:
//   B_leaf = E_leaf + pushed + gathered_leaf
// and radiosity is pulled back up as the area-weighted mean of the children,
//   B_p = sum_c A_c B_c / sum_c A_c
// so that every node holds the mean over its area, which is what a link from it
// carries. Sets B of every node of the subtree and returns B_node.
Color push_pull(Hierarchy& hierarchy, int node, const Color& pushed);

}  // namespace gi
