// Lesson 13: drawing and scoring a hierarchical solution (scoring.hpp).
#include "scoring.hpp"

#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"
#include "gi/radiosity/hierarchical/link_gather.hpp"
#include "gi/radiosity/recipe.hpp"

namespace lesson13 {

Scored score(const Setup& s, const gi::HierarchicalRun& run, Shown shown) {
  Scored out;
  const gi::Timer timer;
  const gi::LeafMesh leaves = gi::leaf_mesh(run.hierarchy);
  const gi::FormFactorScene elements(gi::element_shapes(leaves.mesh));
  const std::vector<gi::Color> B = gi::shown_radiosity(run);
  if (shown == Shown::Leaves) {
    out.picture = gi::render_radiosity_picture(elements, leaves.mesh, B, gi::leaf_vertex_radiosity(leaves, B),
                                               s.scene.camera, s.display, s.seed, s.threads)
                      .radiance;
  } else {
    const std::vector<gi::Color> rest = gi::indirect_part(leaves.mesh, B, run.result.direct);
    const std::vector<gi::Color> at_vertices = shown == Shown::Gathered
                                                   ? gi::gathered_at_vertices(run.hierarchy, leaves, s.threads)
                                                   : gi::leaf_vertex_radiosity(leaves, rest);
    const gi::MeshRadiance bounced{elements, leaves.mesh, rest, at_vertices, gi::Shading::Smooth};
    out.picture = gi::render_display(gi::sum_of(*s.direct, bounced), s.scene.camera, s.display, s.seed, s.threads)
                      .radiance;
    out.seconds = timer.seconds();
  }
  out.error = gi::picture_error(out.picture, s.truth, s.mask).relative_rms;
  return out;
}

gi::HierarchicalSettings with(gi::HierarchicalSettings s, double bf_eps, bool exact_direct) {
  s.refinement.threshold = bf_eps;
  s.exact_direct = exact_direct;
  return s;
}

}  // namespace lesson13
