#include "gi/radiosity/hierarchical/push_pull.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

Color gather(const Hierarchy& h, const Node& receiver, const std::vector<Color>& sent) {
  // BEGIN EXERCISE 13.3 gathering over links
  Color sum(0.0);
  for (const Link& link : receiver.links) {
    const Node& q = h.nodes[link.source];
    if (q.leaf()) {
      sum += link.F * link.visibility * sent[link.source];
      continue;
    }
    // Each quarter of the source sends its share of the light with its own B.
    for (int c = 0; c < 4; ++c) sum += link.F * link.by_quarter[c] * sent[q.children[c]];
  }
  return receiver.rho * sum;
  // END EXERCISE 13.3
}

Color push_pull(Hierarchy& h, int n, const Color& pushed) {
  // BEGIN EXERCISE 13.4 push-pull
  const Color down = pushed + h.nodes[n].gathered;
  if (h.nodes[n].leaf()) return h.nodes[n].B = h.nodes[n].source + h.nodes[n].gather_scale * down;
  Color sum(0.0);
  double area = 0;
  for (int child : h.nodes[n].children) {
    const double a = h.nodes[child].open_area;
    sum += a * push_pull(h, child, down);
    area += a;
  }
  return h.nodes[n].B = area > 0 ? sum / area : h.nodes[n].source + down;  // all buried: nothing to mean
  // END EXERCISE 13.4
}

}  // namespace gi
