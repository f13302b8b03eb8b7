#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/viewer/recording.hpp"

namespace gi {

// What the viewer shows for each radiosity lesson: one call per lesson, e.g.
//   lesson.viewer("...", [&](const std::filesystem::path& file) {
//     gi::write_viewer_data(gi::progressive_replay(...), file);
//   });
// Each stays within about `frame_bytes` of frames (4 MB: a few MB of file). The
// exposure is where the page's slider starts (1.5, as lessons 08 and 11 show the box).
constexpr std::size_t frame_bytes = 4 << 20;

// Lesson 08: the Neumann series term by term -- Jacobi from B = E, whose step k is
// E + RFE + ... + (RF)^k E -- and relighting: the scene's lights and `lamps`, each
// solved alone (solve_per_light). Lamps the scene has no surface for are left out,
// and all of them when nothing emits: the lesson names the Cornell box's surfaces,
// and --scene may give it another scene.
ViewerData neumann_and_relighting(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, int terms, double exposure,
                                  const std::vector<std::string>& lamps);

// Lesson 09: Jacobi, Gauss-Seidel and SOR with `omega`, side by side, `iterations`
// each (error against `reference`), a frame after every iteration as far as they fit.
ViewerData gathering_side_by_side(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, const std::vector<Color>& reference, int iterations,
                                  double omega, double exposure = 1.5);

// Lesson 10: Southwell beside Jacobi and Gauss-Seidel at equal work, `sweeps` sweeps
// of n^2 multiply-adds each (n Southwell steps to a sweep), error against `reference`.
ViewerData southwell_side_by_side(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, const std::vector<Color>& reference, int sweeps,
                                  double exposure = 1.5);

// Lesson 11: progressive refinement replayed shot by shot, up to `shots` shots.
ViewerData progressive_replay(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                              const RadiositySystem& system, const ShooterRow& row, int shots, double exposure);

// Lesson 12: runs the lesson has finished, as curves, and each one's final B.
ViewerData finished_runs(const std::string& lesson, const std::string& title, const RadiosityScene& scene,
                         const Mesh& mesh, const std::vector<SolverResult>& results, double exposure = 1.5);

}  // namespace gi
