#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/hierarchical/hierarchical_solver.hpp"
#include "gi/radiosity/hierarchical/leaf_mesh.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace gi {

// Hierarchical radiosity on a scene, from its surfaces to a picture: what lessons and
// benchmarks do with it. Keeps the hierarchy and its links, so that a new emission
// needs only a new solve (relight) and a new camera only a new picture.
struct HierarchicalRun {
  Hierarchy hierarchy;
  FormFactorScene blockers;  // the input surfaces: the shadow rays' world
  HierarchicalSettings settings;
  HierarchicalResult result;
  double seconds = 0;  // refinements and solves, all rounds
  std::size_t link_bytes = 0;
};
HierarchicalRun run_hierarchical(const RadiosityScene& scene, const HierarchicalSettings& settings, int threads);

// New emission, one per surface (W/m^2), on the links as they stand: a solve from
// B = E, no refinement. The system is linear in E, so the links (F and V) need not
// change; only how finely they were cut was chosen for the old light. Returns the
// solve's result (B per leaf); the hierarchy keeps the new B. Throws
// std::invalid_argument for a wrong count or a negative or non-finite emission, and
// for a run with exact direct light (whose D would have to be recomputed).
SolverResult relight(HierarchicalRun& run, const std::vector<Color>& emission, double tolerance, int threads);

// B of every leaf as the eye sees it (E + B' with exact direct light), in the order of leaves().
std::vector<Color> shown_radiosity(const HierarchicalRun& run);

// The leaves shaded with their vertex colours (leaf_mesh.hpp: no T-vertex cracks),
// and the same picture with the leaves' outlines drawn over it; pixel i's eye rays draw
// from stream i of `seed`, on `threads` threads.
struct LeafPicture {
  RadiosityPicture picture;
  Image with_mesh;  // `shown` with the leaf mesh in dark lines
};
LeafPicture render_leaves(const HierarchicalRun& run, const Camera& camera, const DisplaySettings& settings,
                          std::uint64_t seed, int threads);

}  // namespace gi
