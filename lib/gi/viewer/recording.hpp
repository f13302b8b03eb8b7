#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gi/radiosity/system/progressive.hpp"
#include "gi/viewer/data.hpp"

namespace gi {

// Recording what the viewer replays (viewer_data.hpp): a solver run again with an
// observer that keeps B at chosen steps. Solvers are deterministic, so the run
// recorded is the run the lesson measured.

// The steps to keep a frame of, out of 1..last: all of them when they are at most
// `max_frames`; otherwise every step up to max_frames / 2 (where the picture
// changes most), and the rest spread evenly up to `last`, which is always kept.
std::vector<int> frame_steps(int last, int max_frames);

// How many frames of `elements` elements fit in `bytes` (12 bytes per element per
// frame): at least 2, at most 400.
int frames_within(std::size_t bytes, int elements);

// A solver's run: `solve` is called once with `options`, its observer replaced by
// one that keeps B at `steps` (frames whose B is not finite are left out: a
// diverging solver). Frame 0 is `start`, where the solver begins (B = E for Jacobi
// and Gauss-Seidel, 0 for Southwell); none when it is empty.
using Solve = std::function<SolverResult(const SolverOptions&)>;
ViewerRun record_run(const Solve& solve, SolverOptions options, const std::vector<int>& steps, const std::string& unit,
                     double work_per_step, const std::vector<Color>& start);

// Progressive refinement's run: every frame also names the patch that shot in its
// step (choose_shooter of the unshot radiosity before it) and the ambient term after
// it. Frame 0 is B = E, before the first shot.
ViewerRun record_progressive(const RadiositySystem& system, const Mesh& mesh, const ShooterRow& row,
                             SolverOptions options, const std::vector<int>& steps);

// A run the lesson has finished: its history, thinned to at most `max_rows` rows
// (the last kept), and its final B as the one frame when that is finite.
ViewerRun finished_run(const SolverResult& result, const std::string& unit, double work_per_step, int max_rows = 2000);

// One light per surface that emits (weight 1) and one per surface named in `lamps`,
// made to emit the exitance of the brightest emitting surface (weight 0, so that the
// page starts on the scene as it is). Each is solved alone, (I - RF) B_l = E_l, by
// Gauss-Seidel to a residual of 1e-10 of ||E_l||: the system is linear in E, so the
// page shows sum_l w_l B_l for any weights w_l without solving again. Throws
// std::invalid_argument for a lamp that names no surface, std::runtime_error when
// a light's solution does not converge.
std::vector<ViewerLight> solve_per_light(const RadiositySystem& system, const Mesh& mesh,
                                         const std::vector<std::string>& lamps);

}  // namespace gi
