#include "gi/radiosity/hierarchical/hierarchical_run.hpp"

#include <stdexcept>

#include "gi/core/timer.hpp"
#include "gi/radiosity/hierarchical/mesh_lines.hpp"

namespace gi {

HierarchicalRun run_hierarchical(const RadiosityScene& scene, const HierarchicalSettings& settings, int threads) {
  check(settings);
  Hierarchy hierarchy = make_hierarchy(scene.surfaces);
  FormFactorScene blockers(surface_shapes(hierarchy));
  HierarchicalRun run{std::move(hierarchy), std::move(blockers), settings, {}};
  const Timer timer;
  run.result = solve_hierarchical(run.hierarchy, run.blockers, settings, threads);
  run.seconds = timer.seconds();
  run.link_bytes = link_bytes(run.hierarchy);
  return run;
}

SolverResult relight(HierarchicalRun& run, const std::vector<Color>& emission, double tolerance, int threads) {
  Hierarchy& h = run.hierarchy;
  if (run.settings.exact_direct) throw std::invalid_argument("relight: a run with exact direct light must be solved again");
  if (emission.size() != h.surfaces.size()) throw std::invalid_argument("relight: one emission per surface");
  for (const Color& e : emission)
    if (!is_finite(e) || e.x < 0 || e.y < 0 || e.z < 0)
      throw std::invalid_argument("relight: an emission is negative or not finite");
  for (std::size_t s = 0; s < emission.size(); ++s) h.surfaces[s].emission = emission[s];
  h.largest_emission = 0;
  for (Node& node : h.nodes) {
    node.source = node.B = emission[node.surface];
    h.largest_emission = std::max(h.largest_emission, max_component(node.source));
  }
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_steps = 500;
  return solve_links(h, options, threads);
}

std::vector<Color> shown_radiosity(const HierarchicalRun& run) {
  const Hierarchy& h = run.hierarchy;
  std::vector<Color> B = leaf_radiosity(h);
  if (!run.settings.exact_direct) return B;
  const std::vector<int> leaf = leaves(h);
  for (std::size_t k = 0; k < leaf.size(); ++k) B[k] += h.surfaces[h.nodes[leaf[k]].surface].emission;
  return B;
}

LeafPicture render_leaves(const HierarchicalRun& run, const Camera& camera, const DisplaySettings& settings,
                          std::uint64_t seed, int threads) {
  const LeafMesh leaves = leaf_mesh(run.hierarchy);
  const std::vector<Color> B = shown_radiosity(run);
  const FormFactorScene shapes(element_shapes(leaves.mesh));
  LeafPicture out{render_radiosity_picture(shapes, leaves.mesh, B, leaf_vertex_radiosity(leaves, B), camera, settings,
                                           seed, threads),
                  {}};
  const std::vector<int> ids = visible_polygons(shapes, camera, settings.width, settings.height, threads);
  out.with_mesh = draw_mesh_lines(out.picture.shown, ids, Color(0.0), 0.6);
  return out;
}

}  // namespace gi
