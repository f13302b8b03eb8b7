// Lesson 13, step 1c: the links that light one leaf, drawn over the picture (steps.hpp).
#include <algorithm>
#include <string>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/render/scene_lines.hpp"
#include "steps.hpp"

namespace lesson13 {

// A floor leaf in the open, in front of the tall block: every link it gathers over,
// its own and each ancestor's (push-pull hands what a node gathered to every leaf
// below it), drawn from the leaf to the centre of the node it links to, with that
// node's outline, in the colour of the level that holds the link: red the leaf's own,
// then orange, yellow, green, cyan and blue up to the surface's root. Near sources are
// linked low in the tree, in small pieces; far and dim ones high, whole.
void one_leafs_links(const Setup& s, const gi::HierarchicalRun& run, const gi::Image& picture, gi::Lesson& lesson) {
  const gi::Hierarchy& h = run.hierarchy;
  gi::vec3 lo(1e300), hi(-1e300);
  for (const gi::Node& n : h.nodes)
    if (n.leaf() && h.surfaces[n.surface].name == "floor")
      lo = glm::min(lo, n.shape.centre), hi = glm::max(hi, n.shape.centre);
  const gi::vec3 open_floor = lo + gi::vec3(0.5, 0, 0.12) * (hi - lo);  // front middle, in view
  const auto distance = [&](int k) { return gi::length(h.nodes[k].shape.centre - open_floor); };
  int leaf = -1;
  for (int k = 0; k < static_cast<int>(h.nodes.size()); ++k)
    if (h.nodes[k].leaf() && h.surfaces[h.nodes[k].surface].name == "floor" &&
        (leaf < 0 || distance(k) < distance(leaf)))
      leaf = k;
  if (leaf < 0) return;

  const int scale = 2;  // drawn over the picture enlarged, so that the lines stay apart
  gi::Image shown = gi::enlarge(picture, scale);
  for (gi::Pixel& p : shown.pixels) p = glm::min(gi::Pixel(1), static_cast<float>(s.exposure) * p);
  const gi::CameraFrame frame = gi::camera_frame(s.scene.camera, shown.width, shown.height);
  const gi::Pixel colour[] = {{1, 0.1f, 0.1f}, {1, 0.55f, 0},    {1, 0.95f, 0},
                               {0.2f, 0.9f, 0.2f}, {0, 0.85f, 1}, {0.3f, 0.4f, 1}};
  std::vector<int> path;  // the leaf, its parent, ... the floor's root
  for (int node = leaf; node >= 0; node = h.nodes[node].parent) path.push_back(node);
  std::string counts;
  for (int step = static_cast<int>(path.size()) - 1; step >= 0; --step) {  // the leaf's own drawn last, on top
    const gi::Pixel c = colour[std::min(step, 5)];
    for (const gi::Link& link : h.nodes[path[step]].links) {
      const gi::Polygon& q = h.nodes[link.source].shape;
      gi::draw_segment(shown, frame, h.nodes[leaf].shape.centre, q.centre, c);
      for (int k = 0; k < 4; ++k) gi::draw_segment(shown, frame, q.corners[k], q.corners[(k + 1) % 4], c);
    }
  }
  for (int node : path) counts += (counts.empty() ? "" : ", ") + std::to_string(h.nodes[node].links.size());
  lesson.say("the links that light floor leaf " + std::to_string(leaf) + " (level " +
             std::to_string(h.nodes[leaf].level) + "), its own first, then each ancestor's up to the floor: " + counts);
  lesson.diagram(shown, "one_leafs_links",
                 "the links one floor leaf gathers over, each drawn to the node it links to and that node's outline: "
                 "red the leaf's own, then orange, yellow, green, cyan and blue for its ancestors' up to the floor",
                 1);
}

}  // namespace lesson13
