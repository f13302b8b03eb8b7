#pragma once
#include <filesystem>
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"

namespace gi {

// Radiosity is computed per element, constant over each; drawn like that the mesh
// shows every element as a tile. Gouraud's cure: give every vertex the area-weighted
// mean of the elements that share it,
//   B_v = sum over elements e at v of A_e B_e / sum of A_e,
// and interpolate across each element from its four corners.
std::vector<Color> vertex_radiosity(const Mesh& mesh, const std::vector<Color>& B);

// The mesh as an ASCII PLY file with a colour per vertex (MeshLab, Blender): the
// vertex radiosity as radiance L = B / pi, times `exposure`, clamped and
// sRGB-encoded to 8 bits. Faces are the elements (quadrilaterals). Written
// atomically; throws std::runtime_error for a NaN or infinite radiosity.
void write_ply(const Mesh& mesh, const std::vector<Color>& vertex_B, double exposure,
               const std::filesystem::path& file);
// The same with the faces given as outlines of vertex indices (any count from 3, counter-clockwise),
// e.g. leaves with the T-vertices along their edges (leaf_mesh.hpp).
void write_ply(const Mesh& mesh, const std::vector<Color>& vertex_B, double exposure, const std::filesystem::path& file,
               const std::vector<std::vector<int>>& faces);

}  // namespace gi
