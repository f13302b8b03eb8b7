#include "gi/viewer/hierarchical.hpp"

#include "gi/radiosity/hierarchical/push_pull.hpp"

namespace gi {

namespace {

// Nodes, links and what each leaf was handed, read off the hierarchy.
ViewerHierarchy hierarchy_of(const HierarchicalRun& run, const LeafMesh& leaves) {
  const Hierarchy& h = run.hierarchy;
  ViewerHierarchy out;
  out.links_carry = run.settings.exact_direct
                        ? "light that has bounced at least once: the direct light D is exact (shadow rays to the "
                          "light), not a link's; B = E + D + what the links bring"
                        : "all the light: B = E + what the links bring";
  std::vector<Color> sent;
  sent.reserve(h.nodes.size());
  for (const Node& node : h.nodes) {
    out.node_surface.push_back(node.surface);
    out.node_level.push_back(node.level);
    out.node_parent.push_back(node.parent);
    out.node_corners.push_back(node.shape.corners);
    sent.push_back(node.sent);
  }
  // One link at a time, as gather() weighs it, with rho = 1: the light before rho.
  Node alone;
  alone.rho = Color(1.0);
  alone.links.resize(1);
  for (const Node& node : h.nodes)
    for (const Link& link : node.links) {
      alone.links[0] = link;
      out.links.push_back({link.receiver, link.source, link.F, link.visibility, gather(h, alone, sent)});
    }
  out.element_node = leaves.node;
  for (int leaf : leaves.node) {
    Color handed(0.0);  // what push-pull gave the leaf: its own gather and its ancestors'
    for (int n = leaf; n >= 0; n = h.nodes[n].parent) handed += h.nodes[n].gathered;
    out.element_gathered.push_back(handed);
  }
  for (const LeafMesh::TVertex& tv : leaves.t_vertices) out.t_vertices.push_back({tv.vertex, tv.a, tv.b, tv.t});
  return out;
}

}  // namespace

ViewerData hierarchical_viewer_data(const std::string& lesson, const std::string& title, const HierarchicalRun& run,
                                    const Camera& camera, double exposure) {
  const LeafMesh leaves = leaf_mesh(run.hierarchy);
  ViewerData d = viewer_data(lesson, title, leaves.mesh, camera, exposure);
  const SolverResult& solution = run.result.solution;
  // Work per step 1, unused: an iteration is a pass over the links, not a sweep of n^2
  // multiply-adds, and the page offers no work axis for a hierarchy.
  ViewerRun shown{"hierarchical", "iteration", stop_reason(solution, "iteration"), 1, solution.history, {}, false};
  shown.frames.push_back({solution.history.empty() ? 0 : solution.history.back().step, shown_radiosity(run)});
  d.runs.push_back(std::move(shown));
  d.hierarchy = hierarchy_of(run, leaves);
  return d;
}

}  // namespace gi
