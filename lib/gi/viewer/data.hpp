#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/solver.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// What the interactive viewer (docs/viewer/viewer.html, docs/viewer.md) shows: a
// mesh of quadrilateral elements and, on it, radiosities step by step (a run's
// frames), solver histories (its curves) and one solution per light (relighting).
//
// The file, viewer_data.js, is a script the page loads with <script src>: the one
// way a page opened with file:// may read a file beside it (fetch() is refused).
// It holds one statement, `window.GI_VIEWER_DATA = <JSON>;`, the JSON being
// (format 1; every key below is always present unless marked optional):
//
//   format "gi-workbench viewer", version 1, lesson, title   strings, the number 1
//   exposure          the page shows L = B / pi times this, clamped, sRGB-encoded
//   camera            {eye, look_at, up: [x, y, z], vertical_fov_degrees}
//   mesh              vertices  float32, 3 per vertex (scene units)
//                     elements  uint32, 4 per element: its corners, counter-clockwise
//                               seen from the lit side (mesh.hpp)
//                     element_patch, element_surface  int32, 1 per element
//                     area float32 (A_i); reflectance, emission float32, 3 per element
//                     surfaces  the surfaces' names; patches  the number of patches
//   runs              [{name, unit ("iteration", "shot" ...), status, work_per_step
//                     (sweeps of n^2 multiply-adds: 1 for an iteration, 1/n for a
//                     Southwell step or a shot),
//                     history: {step int32; residual_2, residual_inf, unshot,
//                               seconds float32; error float32 (optional: with a
//                               reference)} -- one entry per recorded step,
//                     frames:  {step int32; B float32, 3 per element per frame;
//                               shooter int32 (optional: the patch that shot in that
//                               step); ambient float32, 3 per frame (optional: the
//                               ambient term after it)}}]
//   lights            [{name, weight, emission, B}]: E of that light alone and the
//                     solution of (I - RF) B = E for it; the page shows sum_l w_l B_l
//                     with w_l starting at weight. May be empty.
//
// A typed array is {"type": "float32" | "int32" | "uint32", "count": n, "base64":
// ...}, its n values little-endian. Readers ignore keys they do not know, so a
// later lesson can add its own without changing the version, as hierarchical
// radiosity (lesson 13) does:
//
//   hierarchy         (optional) the elements are the leaves of quadtrees of nodes
//     links_carry     what the links' light is, in words (all light, or only what
//                     has bounced when the direct light is exact)
//     nodes           surface, level, parent int32 (-1: a root; a parent comes
//                     before its children), 1 per node;
//                     corners float32, 12 per node: its four corners in the order
//                     of mesh.elements
//     element_node    int32, 1 per element: the leaf node it is
//     element_gathered  float32, 3 per element: what push-pull handed the leaf in
//                     the solver's last step, rho times the light over the links
//                     of the leaf and of all its ancestors
//     links           receiver, source int32 (nodes), F, visibility float32, 1 per
//                     link; light float32, 3 per link: the radiosity the link
//                     brings its receiver before rho, F sum_c V_c B_c over the
//                     source's quarters (push_pull.hpp's gather), B the nodes
//                     hold after the solve (with exact direct light that is
//                     B' = B - E, which the links carry: hierarchical_solver.hpp)
//     t_vertices      vertex, a, b int32, t float32, 1 per T-vertex, coarsest
//                     first: a smooth picture sets B_v = (1 - t) B_a + t B_b after
//                     the area-weighted mean, so no crack opens (leaf_mesh.hpp)
struct ViewerFrame {
  int step = 0;
  std::vector<Color> B;  // one per element
  int shooter = -1;      // progressive refinement: the patch that shot in this step; -1 none
  Color ambient{0.0};    // progressive refinement: the ambient term after this step
};

struct ViewerRun {
  std::string name, unit, status;
  double work_per_step = 1;
  std::vector<SolverStep> history;
  std::vector<ViewerFrame> frames;
  bool shooters = false;  // frames carry `shooter` and `ambient`
};

struct ViewerLight {
  std::string name;
  double weight = 1;
  std::vector<Color> emission, B;  // one per element
};

// The hierarchy of a hierarchical run, as the page shows it (viewer_hierarchy.hpp).
struct ViewerLink {
  int receiver = -1, source = -1;  // nodes
  double F = 0, visibility = 0;
  Color light{0.0};  // F sum_c V_c B_c: what it brings the receiver before rho
};
struct ViewerTVertex {
  int vertex = -1, a = -1, b = -1;
  double t = 0;
};
struct ViewerHierarchy {
  std::string links_carry;
  std::vector<int> node_surface, node_level, node_parent;
  std::vector<std::array<vec3, 4>> node_corners;
  std::vector<int> element_node;
  std::vector<Color> element_gathered;
  std::vector<ViewerLink> links;
  std::vector<ViewerTVertex> t_vertices;
};

struct ViewerData {
  std::string lesson, title;
  double exposure = 1;
  Camera camera;
  std::vector<vec3> vertices;
  std::vector<std::array<int, 4>> elements;
  std::vector<int> element_patch, element_surface;
  std::vector<double> area;
  std::vector<Color> reflectance, emission;
  std::vector<std::string> surfaces;
  int patches = 0;
  std::vector<ViewerRun> runs;
  std::vector<ViewerLight> lights;
  std::optional<ViewerHierarchy> hierarchy;
};

// The mesh part of the data, from a radiosity mesh.
ViewerData viewer_data(const std::string& lesson, const std::string& title, const Mesh& mesh, const Camera& camera,
                       double exposure);

// The whole file's text. Throws std::invalid_argument naming the first problem: an
// array of the wrong length, a corner or patch index out of range, a value that is
// not finite in the mesh, a frame or a light (float32 included: |x| > 3.4e38); in
// the hierarchy, a node, element, vertex or parent index out of range, a visibility
// outside [0, 1] or a value that is not finite.
// History values may be NaN or infinite (a diverging solver); the page skips them.
std::string viewer_data_text(const ViewerData& data);

// viewer_data_text written atomically (atomic_file.hpp); throws as it does, or WriteError.
void write_viewer_data(const ViewerData& data, const std::filesystem::path& file);

}  // namespace gi
