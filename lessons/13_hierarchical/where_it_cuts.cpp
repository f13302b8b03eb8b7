// Lesson 13, step 2b: where the hierarchy cuts the surfaces, beside a uniform mesh of
// as many elements (steps.hpp).
#include <string>

#include "gi/image/diff.hpp"
#include "gi/radiosity/display/element_values.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/hierarchical/leaf_mesh.hpp"
#include "gi/report/table.hpp"
#include "steps.hpp"

namespace lesson13 {

// At BF_eps 1e-2, all light by links, and nodes allowed down to a tenth of the
// lesson's smallest: loose enough that most of the box stays coarse, small enough that
// the leaves can crowd where a link's light changes fast across its receiver -- at the
// feet of the blocks and in their shadows, along the corners where two walls meet,
// around the light. The uniform mesh spends the same number of elements evenly.
void where_it_cuts(const Setup& s, gi::Lesson& lesson) {
  gi::HierarchicalSettings loose = with(s.settings, 1e-2, false);
  loose.refinement.min_area = s.settings.refinement.min_area / 10;
  const gi::HierarchicalRun run = gi::run_hierarchical(s.scene, loose, s.threads);
  const gi::LeafMesh leaves = gi::leaf_mesh(run.hierarchy);
  const int n = static_cast<int>(leaves.mesh.elements.size());
  const gi::Mesh uniform = gi::make_mesh(s.scene.surfaces, {gi::patch_size_for(s.scene.surfaces, n, 1), 1});
  lesson.say("\nwhere the hierarchy cuts (BF_eps 1e-2, all light by links, min area " +
             gi::format_number(loose.refinement.min_area, 0, gi::Format::Scientific) + "): " + std::to_string(n) +
             " leaves, beside a uniform mesh of " + std::to_string(uniform.elements.size()) + " elements");
  const int side = 384;
  const gi::ElementSizes adaptive = gi::render_element_sizes(leaves.mesh, s.scene.camera, side, side, 0, s.threads);
  const gi::ElementSizes even = gi::render_element_sizes(uniform, s.scene.camera, side, side, adaptive.top, s.threads);
  lesson.diagram(gi::side_by_side({adaptive.image, even.image}), "where_it_cuts",
                 "how finely the box is cut: the hierarchy's " + std::to_string(n) +
                     " leaves at BF_eps 1e-2 (all light by links, nodes down to a tenth of the lesson's --min-area), "
                     "beside a uniform mesh of " + std::to_string(uniform.elements.size()) + " elements",
                 gi::ColourScale{0, adaptive.top, "log4(A_largest surface / A_element): quarterings of a wall", false});
}

}  // namespace lesson13
