#include "gi/radiosity/hierarchical/leaf_mesh.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

namespace {

// Corners in whole units of the finest leaf of the surface: a node of level l is
// 2^(depth - l) units wide. The four directions around a vertex are probed at half
// units, so probes count in halves.
struct Grid {
  int depth;  // the deepest level of the surface's leaves
  long long width(int level) const { return 1LL << (depth - level); }
};

// The leaf of surface `root` that contains the probe (qx, qy), in half units; -1 outside.
int leaf_at(const Hierarchy& h, int root, const Grid& grid, long long qx, long long qy) {
  const long long size = 2LL << grid.depth;
  if (qx <= 0 || qy <= 0 || qx >= size || qy >= size) return -1;
  int n = root;
  while (!h.nodes[n].leaf()) {
    const int shift = grid.depth - h.nodes[n].level;  // a child is 2^shift halves wide
    const int k = static_cast<int>(((qx >> shift) & 1) + 2 * ((qy >> shift) & 1));
    n = h.nodes[n].children[k];
  }
  return n;
}

}  // namespace

LeafMesh leaf_mesh(const Hierarchy& h) {
  LeafMesh out;
  out.mesh.surfaces = h.surfaces;
  out.node = leaves(h);
  std::vector<Grid> grids(h.surfaces.size(), Grid{0});
  for (int n : out.node) grids[h.nodes[n].surface].depth = std::max(grids[h.nodes[n].surface].depth, h.nodes[n].level);
  // Vertices by (surface, x, y) in whole units.
  std::map<std::array<long long, 3>, int> vertex;
  const auto corner = [&](const Node& node, int k) {
    const long long w = grids[node.surface].width(node.level);
    return std::array<long long, 3>{node.surface, (node.i + (k == 1 || k == 2)) * w, (node.j + (k >= 2)) * w};
  };
  for (std::size_t e = 0; e < out.node.size(); ++e) {
    const Node& leaf = h.nodes[out.node[e]];
    Element element{leaf.shape, leaf.surface, leaf.surface, {}};
    for (int k = 0; k < 4; ++k) {
      const auto [it, added] = vertex.try_emplace(corner(leaf, k), static_cast<int>(out.mesh.vertices.size()));
      if (added) out.mesh.vertices.push_back(leaf.shape.corners[k]);
      element.vertices[k] = it->second;
    }
    if (out.mesh.patches.empty() || out.mesh.patches.back().surface != leaf.surface)
      out.mesh.patches.push_back({h.nodes[leaf.surface].shape, leaf.surface, static_cast<int>(e), 0});
    ++out.mesh.patches.back().element_count;
    out.mesh.elements.push_back(element);
  }
  // A vertex inside an edge of a larger leaf: probe the four quarters around it.
  std::map<int, int> element_of;  // node -> element
  for (std::size_t e = 0; e < out.node.size(); ++e) element_of[out.node[e]] = static_cast<int>(e);
  std::vector<std::pair<int, LeafMesh::TVertex>> found;  // (level of the large leaf, T-vertex)
  std::vector<std::vector<std::pair<double, int>>> on_edge(4 * out.node.size());  // (t, vertex) per element edge
  for (const auto& [key, v] : vertex) {
    const auto [surface, x, y] = key;
    const Grid& grid = grids[surface];
    for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}) {
      const int n = leaf_at(h, static_cast<int>(surface), grid, 2 * x + dx, 2 * y + dy);
      if (n < 0) continue;
      const Node& leaf = h.nodes[n];
      const long long w = grid.width(leaf.level), x0 = leaf.i * w, y0 = leaf.j * w;
      const bool on_vertical = x % w == 0, on_horizontal = y % w == 0;
      if (on_vertical && on_horizontal) continue;  // one of its corners
      const int e = element_of.at(n);
      const auto& corners = out.mesh.elements[e].vertices;
      // Edges k: corner k to corner k + 1 (0: bottom, 1: right, 2: top, 3: left).
      int edge;
      double t;
      if (on_vertical) {
        edge = x == x0 ? 3 : 1;
        t = static_cast<double>(y - y0) / w;
      } else {
        edge = y == y0 ? 0 : 2;
        t = static_cast<double>(x - x0) / w;
      }
      if (edge >= 2) t = 1 - t;  // edges 2 and 3 run backwards in x or y
      const int a = corners[edge], b = corners[(edge + 1) % 4];
      found.push_back({leaf.level, {v, a, b, t}});
      on_edge[4 * e + edge].push_back({t, v});
      break;
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  for (const auto& f : found) out.t_vertices.push_back(f.second);
  for (std::size_t e = 0; e < out.node.size(); ++e) {
    std::vector<int> face;
    for (int edge = 0; edge < 4; ++edge) {
      face.push_back(out.mesh.elements[e].vertices[edge]);
      auto& along = on_edge[4 * e + edge];
      std::sort(along.begin(), along.end());
      for (const auto& [t, v] : along) face.push_back(v);
    }
    out.faces.push_back(std::move(face));
  }
  return out;
}

void settle_t_vertices(const LeafMesh& leaves, std::vector<Color>& vertex_values) {
  for (const LeafMesh::TVertex& tv : leaves.t_vertices)
    vertex_values[tv.vertex] = (1 - tv.t) * vertex_values[tv.a] + tv.t * vertex_values[tv.b];
}

std::vector<Color> leaf_vertex_radiosity(const LeafMesh& leaves, const std::vector<Color>& B) {
  std::vector<Color> vertex_B = vertex_radiosity(leaves.mesh, B);
  settle_t_vertices(leaves, vertex_B);
  return vertex_B;
}

}  // namespace gi
