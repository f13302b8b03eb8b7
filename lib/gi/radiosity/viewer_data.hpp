#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "gi/radiosity/mesh.hpp"
#include "gi/radiosity/solver.hpp"
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
// later lesson can add its own: hierarchical radiosity will add "hierarchy" (its
// nodes, the leaf node of each element, and links {receiver, source, F} as typed
// arrays) without changing the version.
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
};

// The mesh part of the data, from a radiosity mesh.
ViewerData viewer_data(const std::string& lesson, const std::string& title, const Mesh& mesh, const Camera& camera,
                       double exposure);

// The whole file's text. Throws std::invalid_argument naming the first problem: an
// array of the wrong length, a corner or patch index out of range, a value that is
// not finite in the mesh, a frame or a light (float32 included: |x| > 3.4e38).
// History values may be NaN or infinite (a diverging solver); the page skips them.
std::string viewer_data_text(const ViewerData& data);

// viewer_data_text written atomically (atomic_file.hpp); throws as it does, or WriteError.
void write_viewer_data(const ViewerData& data, const std::filesystem::path& file);

}  // namespace gi
