#include "gi/radiosity/hierarchical/hierarchy.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gi {

Hierarchy make_hierarchy(const std::vector<Surface>& surfaces) {
  // One element per surface: make_mesh checks the surfaces and their overlaps.
  const Mesh mesh = make_mesh(surfaces, {1e300, 1});
  Hierarchy h;
  h.surfaces = surfaces;
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    Node root;
    root.shape = mesh.elements[s].shape;
    root.surface = static_cast<int>(s);
    root.rho = surfaces[s].reflectance;
    root.source = root.B = root.sent = surfaces[s].emission;
    root.open_area = root.shape.area;
    h.nodes.push_back(root);
    h.lifts.push_back(lift(root.shape));
    h.total_area += root.shape.area;
    h.largest_emission = std::max(h.largest_emission, max_component(root.source));
  }
  return h;
}

vec3 node_point(const Hierarchy& h, const Node& node, double u, double v) {
  const double scale = 1.0 / static_cast<double>(1LL << node.level);
  return bilinear(h.surfaces[node.surface].corners, (node.i + u) * scale, (node.j + v) * scale);
}

void split(Hierarchy& h, int index) {
  if (!h.nodes[index].leaf()) throw std::invalid_argument("hierarchy: node " + std::to_string(index) + " is split already");
  const int first = static_cast<int>(h.nodes.size());
  for (int k = 0; k < 4; ++k) {
    const Node& parent = h.nodes[index];
    Node child;
    child.surface = parent.surface;
    child.level = parent.level + 1;
    child.i = 2 * parent.i + (k & 1);
    child.j = 2 * parent.j + (k >> 1);
    child.parent = index;
    child.rho = parent.rho, child.source = parent.source, child.B = parent.B, child.sent = parent.sent;
    const double scale = 1.0 / static_cast<double>(1LL << child.level);
    const std::array<vec3, 4>& c = h.surfaces[child.surface].corners;
    const double s0 = child.i * scale, s1 = (child.i + 1) * scale, t0 = child.j * scale, t1 = (child.j + 1) * scale;
    child.shape = make_polygon({bilinear(c, s0, t0), bilinear(c, s1, t0), bilinear(c, s1, t1), bilinear(c, s0, t1)});
    child.open_area = child.shape.area;
    h.nodes.push_back(std::move(child));  // may move the nodes: `parent` is looked up again each time
  }
  for (int k = 0; k < 4; ++k) h.nodes[index].children[k] = first + k;
}

vec3 lifted_point(const Hierarchy& h, const Node& node, double u, double v) {
  return lifted(h, node.surface, node_point(h, node, u, v));
}

vec3 lifted(const Hierarchy& h, int surface, const vec3& p) {
  const Polygon& shape = h.nodes[surface].shape;  // the root: the whole surface
  // Cached by make_hierarchy; a hierarchy put together by hand has no cache.
  const std::size_t s = static_cast<std::size_t>(surface);
  const double up = s < h.lifts.size() ? h.lifts[s] : lift(shape);
  return p + (up - dot(p - shape.centre, shape.normal)) * shape.normal;
}

std::vector<Polygon> surface_shapes(const Hierarchy& h) {
  std::vector<Polygon> shapes;
  for (std::size_t s = 0; s < h.surfaces.size(); ++s) shapes.push_back(h.nodes[s].shape);  // the roots
  return shapes;
}

int leaf_containing(const Hierarchy& h, int surface, double s, double t) {
  if (surface < 0 || surface >= static_cast<int>(h.surfaces.size()))
    throw std::invalid_argument("hierarchy: no surface " + std::to_string(surface));
  s = std::clamp(s, 0.0, 1.0), t = std::clamp(t, 0.0, 1.0);
  int n = surface;
  while (!h.nodes[n].leaf()) {
    // The child's half in each direction: the next binary digit of s and t.
    const double scale = static_cast<double>(2LL << h.nodes[n].level);
    const int x = std::min(static_cast<int>(s * scale), 2 * h.nodes[n].i + 1) - 2 * h.nodes[n].i;
    const int y = std::min(static_cast<int>(t * scale), 2 * h.nodes[n].j + 1) - 2 * h.nodes[n].j;
    n = h.nodes[n].children[std::clamp(x, 0, 1) + 2 * std::clamp(y, 0, 1)];
  }
  return n;
}

std::vector<int> leaves(const Hierarchy& h) {
  std::vector<int> out, stack;
  for (int root = static_cast<int>(h.surfaces.size()) - 1; root >= 0; --root) stack.push_back(root);
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    const Node& node = h.nodes[n];
    if (node.leaf()) {
      out.push_back(n);
      continue;
    }
    for (int k = 3; k >= 0; --k) stack.push_back(node.children[k]);
  }
  return out;
}

std::size_t link_count(const Hierarchy& h) {
  std::size_t n = 0;
  for (const Node& node : h.nodes) n += node.links.size();
  return n;
}

std::size_t link_bytes(const Hierarchy& h) {
  std::size_t n = 0;
  for (const Node& node : h.nodes) n += node.links.capacity() * sizeof(Link);
  return n;
}

}  // namespace gi
