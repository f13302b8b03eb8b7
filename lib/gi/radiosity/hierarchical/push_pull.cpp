#include "gi/radiosity/hierarchical/push_pull.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

Color gather(const Node& receiver, const std::vector<Color>& B) {
  // BEGIN EXERCISE 13.3 gathering over links
  Color sum(0.0);
  for (const Link& link : receiver.links) sum += link.F * link.visibility * B[link.source];
  return receiver.rho * sum;
  // END EXERCISE 13.3
}

Color push_pull(Hierarchy& h, int n, const Color& pushed) {
  // BEGIN EXERCISE 13.4 push-pull
  const Color down = pushed + h.nodes[n].gathered;
  if (h.nodes[n].leaf()) return h.nodes[n].B = h.nodes[n].E + down;
  Color sum(0.0);
  double area = 0;
  for (int child : h.nodes[n].children) {
    const double a = h.nodes[child].shape.area;
    sum += a * push_pull(h, child, down);
    area += a;
  }
  return h.nodes[n].B = sum / area;
  // END EXERCISE 13.4
}

}  // namespace gi
