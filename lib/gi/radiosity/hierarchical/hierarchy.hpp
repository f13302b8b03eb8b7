#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gi/radiosity/hierarchical/link.hpp"
#include "gi/radiosity/mesh/mesh.hpp"

namespace gi {

// Hierarchical radiosity (Hanrahan, Salzman and Aupperle 1991) keeps every input
// surface whole, as the root of a quadtree, and cuts a node into four only where a
// link needs it (oracle.hpp). The nodes live in one vector and name each other by
// index, as the BVH's nodes do.
//
// A node is the square [i, i + 1] x [j, j + 1] / 2^level of its surface's parameter
// square, mapped onto the surface by polygon.hpp's bilinear map: its four children
// cut it at the middle in both directions, so they tile it exactly and share their
// corners with their neighbours.
struct Node {
  Polygon shape;
  int surface = 0;
  int level = 0, i = 0, j = 0;  // its square in the surface's parameter square
  int parent = -1;
  // Children (2i, 2j), (2i + 1, 2j), (2i, 2j + 1), (2i + 1, 2j + 1) at level + 1; -1: a leaf.
  std::array<int, 4> children{-1, -1, -1, -1};
  Color rho{0.0};  // its surface's reflectance
  // The source term of the equation solved at a leaf, B = source + gather_scale * (what
  // its links and its ancestors' bring, times rho): its surface's emission E (W/m^2), or
  // with exact direct light (hierarchical_solver.hpp) D, the direct light it reflects.
  Color source{0.0};
  // At a leaf, its radiosity; above, the area-weighted mean of its children's (push-pull).
  Color B{0.0};
  // What its links carry away from it: at a leaf B times send_scale, above the
  // area-weighted mean of its children's (hierarchical_solver.cpp's pull_sent).
  Color sent{0.0};
  // rho times what its own links bring in, before push-pull hands it to its leaves.
  Color gathered{0.0};
  // A leaf's two balance factors (balance.hpp), 1 until the links are balanced: what
  // reaches the leaf is multiplied by gather_scale, what it sends by send_scale.
  double gather_scale = 1, send_scale = 1;
  std::vector<Link> links;  // the links it receives over
  // Its open part, what is not buried inside a solid (exposure.hpp): a bit per cell of
  // a 4 x 4 grid, and an area (a leaf's share of open cells times its area, above that
  // the sum of its children's). Until measured: all of it.
  std::uint16_t open = 0xFFFF;
  double open_area = 0;

  bool leaf() const { return children[0] < 0; }
};

struct Hierarchy {
  std::vector<Surface> surfaces;
  std::vector<Node> nodes;  // nodes[s] is the root of surface s
  double total_area = 0;    // of all surfaces
  double largest_emission = 0;  // max over surfaces and channels of E: the scale of BF-refinement
  int exposed = 0;  // nodes [0, exposed) have their open cells judged (exposure.hpp)
  std::vector<double> lifts;  // lift(surface s's polygon), polygon.hpp: for lifted_point, at every shadow ray's ends
};

// One root per surface, every B = source = E, no links. Throws std::invalid_argument for a bad
// surface or two that overlap in one plane (the checks of make_mesh).
Hierarchy make_hierarchy(const std::vector<Surface>& surfaces);

// Cuts leaf `node` into four: the children get its surface, rho, source and its B (the best
// guess until a solve). Appends to nodes, so references into it become invalid.
// Throws std::invalid_argument for a node that is not a leaf.
void split(Hierarchy& hierarchy, int node);

// The point (u, v) in [0, 1]^2 of a node, on its surface's bilinear map.
vec3 node_point(const Hierarchy& hierarchy, const Node& node, double u, double v);

// The same point moved along its surface's normal onto the plane through the
// surface's lifted centre (polygon.hpp; a no-op on a flat surface): where shadow rays
// start, so that a twisted surface never hides its own points.
vec3 lifted_point(const Hierarchy& hierarchy, const Node& node, double u, double v);
// Any point p of surface `surface` moved so.
vec3 lifted(const Hierarchy& hierarchy, int surface, const vec3& p);

// The input surfaces' polygons (the roots' shapes): what shadow rays are cast against.
std::vector<Polygon> surface_shapes(const Hierarchy& hierarchy);

// The leaf of surface `surface` that holds the point (s, t) of the surface's
// parameter square (bilinear's), found by walking down from the root: at level l the
// child is picked by the l-th binary digit of s and t. Throws std::invalid_argument
// for a surface out of range; s and t are clamped into [0, 1].
int leaf_containing(const Hierarchy& hierarchy, int surface, double s, double t);

// The leaves, surface by surface, each quadtree depth first: the mesh that is shown.
std::vector<int> leaves(const Hierarchy& hierarchy);
std::size_t link_count(const Hierarchy& hierarchy);
// Bytes held by the links (the vectors' capacity, not their size): what the paper's
// O(n) claim is about.
std::size_t link_bytes(const Hierarchy& hierarchy);

}  // namespace gi
