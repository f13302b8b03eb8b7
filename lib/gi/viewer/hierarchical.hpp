#pragma once
#include <string>

#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/viewer/data.hpp"

namespace gi {

// What the viewer shows of a hierarchical run (lesson 13, docs/viewer.md): its leaves
// as the mesh (leaf_mesh.hpp), the B the lessons show on them (shown_radiosity) as
// the run's one frame, and the hierarchy: every node, every link with the light it
// carries, the leaf node of each element and what push-pull handed that leaf, and
// the T-vertices, so that the page shades the leaves without cracks.
//
// A link's light is its share of the receiver's gather (push_pull.hpp), taken
// alone and before rho:
//   light_l = F_l sum_c V_l,c B_c       (a leaf source: F_l V_l B_q)
// with the B the nodes hold now. A leaf gathers over its own links and, by
// push-pull, over its ancestors' (B_leaf = E + sum over them of rho light_l once the
// solve has converged): the page lists those links when a student picks the leaf.
ViewerData hierarchical_viewer_data(const std::string& lesson, const std::string& title, const HierarchicalRun& run,
                                    const Camera& camera, double exposure);

}  // namespace gi
