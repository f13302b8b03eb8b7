#pragma once
#include <vector>

#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// The leaves of a hierarchy as a Mesh, for the display and PLY: one element per leaf
// (in the order of leaves()), one patch per surface, and vertices shared by the
// leaves of a surface that meet there.
//
// Neighbouring leaves of different sizes meet at T-vertices: the corner of a small
// leaf that lies inside the edge of a large one. Gouraud shading would interpolate
// the large leaf's edge from its two ends but the small leaves from their own
// corners, so the shading jumps along the edge -- a crack. The cure used here: a
// T-vertex does not average its leaves; it takes the value the large leaf's edge has
// there, interpolated from that edge's ends,
//   B_v = (1 - t) B_a + t B_b
// (the ends first, as they may hang on a larger edge themselves). Both sides of the
// edge then interpolate the same values: no crack. For PLY, a large leaf's face
// lists the T-vertices along its edges, so no renderer sees a T-junction either.
struct LeafMesh {
  Mesh mesh;
  std::vector<int> node;  // the hierarchy node of each element
  // A T-vertex: vertex, the ends a and b of the edge it lies in, and where, t in (0, 1).
  struct TVertex {
    int vertex, a, b;
    double t;
  };
  std::vector<TVertex> t_vertices;      // coarsest edges first: ends settled before what hangs on them
  std::vector<std::vector<int>> faces;  // each element's outline, T-vertices included (counter-clockwise)
};
LeafMesh leaf_mesh(const Hierarchy& hierarchy);

// Vertex radiosities for Gouraud shading: the area-weighted mean of the leaves around
// each vertex (vertex_colours.hpp), then every T-vertex set from its edge as above.
// `B` holds one radiosity per element.
std::vector<Color> leaf_vertex_radiosity(const LeafMesh& leaves, const std::vector<Color>& B);

// The cure itself, on any values held one per vertex: every T-vertex set from the ends
// of its edge, B_v = (1 - t) B_a + t B_b, coarsest edges first.
void settle_t_vertices(const LeafMesh& leaves, std::vector<Color>& vertex_values);

}  // namespace gi
