#include "gi/radiosity/hierarchical/exposure.hpp"

#include <algorithm>
#include <cmath>

#include "gi/core/onb.hpp"
#include "gi/core/parallel.hpp"

namespace gi {

bool buried(const FormFactorScene& blockers, const vec3& point, const vec3& normal, double scene_size) {
  const Onb frame(normal);
  const double c = 0.5, s = std::sqrt(3.0) / 2;  // cos and sin of 60 degrees
  for (const vec3& d : {normal, c * normal + s * frame.u, c * normal - s * frame.u, c * normal + s * frame.v,
                        c * normal - s * frame.v}) {
    const auto hit = blockers.first_hit(Ray{point, d, 1e-7 * scene_size});
    if (!hit || hit->front) return false;  // the room, or the outside of something in it
  }
  return true;
}

std::uint16_t open_cells(const FormFactorScene& blockers, const Hierarchy& h, int node) {
  const Node& n = h.nodes[node];
  const double size = std::sqrt(h.total_area);
  std::uint16_t open = 0;
  for (int v = 0; v < exposure_cells; ++v)
    for (int u = 0; u < exposure_cells; ++u) {
      const vec3 centre = lifted_point(h, n, (u + 0.5) / exposure_cells, (v + 0.5) / exposure_cells);
      if (!buried(blockers, centre, n.shape.normal, size)) open |= static_cast<std::uint16_t>(1u << (exposure_cells * v + u));
    }
  return open;
}

bool open_at(const Node& node, double u, double v) {
  const int cu = std::min(static_cast<int>(u * exposure_cells), exposure_cells - 1);
  const int cv = std::min(static_cast<int>(v * exposure_cells), exposure_cells - 1);
  return (node.open >> (exposure_cells * cv + cu)) & 1u;
}

void measure_exposure(Hierarchy& h, const FormFactorScene& blockers, int first, int threads) {
  const int end = static_cast<int>(h.nodes.size());
  parallel_for(end - first, threads, [&](int k) { h.nodes[first + k].open = open_cells(blockers, h, first + k); });
  // Children come after their parent in the vector: backwards, a node's children are summed before it.
  constexpr double cells = exposure_cells * exposure_cells;
  for (int n = end - 1; n >= 0; --n) {
    Node& node = h.nodes[n];
    if (node.leaf()) {
      node.open_area = node.shape.area * __builtin_popcount(node.open) / cells;
      continue;
    }
    node.open_area = 0;
    for (int child : node.children) node.open_area += h.nodes[child].open_area;
  }
}

}  // namespace gi
