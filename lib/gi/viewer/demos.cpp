#include "gi/viewer/demos.hpp"

#include <algorithm>

#include "gi/radiosity/system/solvers.hpp"

namespace gi {

namespace {

// A solver run with frames at `last` steps or fewer, within a share of frame_bytes.
ViewerRun watched(const Solve& solve, int last, int runs, const RadiositySystem& system, SolverOptions options,
                  const std::string& unit, double work_per_step, const std::vector<Color>& start) {
  options.max_steps = last;
  const int frames = frames_within(frame_bytes / std::max(1, runs), system.size());
  return record_run(solve, options, frame_steps(last, frames), unit, work_per_step, start);
}

SolverOptions against(const std::vector<Color>& reference) {
  SolverOptions options;
  options.tolerance = 0;  // every step, as the lessons' tables do
  options.reference = &reference;
  return options;
}

}  // namespace

ViewerData neumann_and_relighting(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, int terms, double exposure,
                                  const std::vector<std::string>& lamps) {
  ViewerData data = viewer_data(lesson, "The Neumann series term by term; relighting by linearity", mesh, scene.camera,
                                exposure);
  SolverOptions options;
  options.tolerance = 0;
  ViewerRun series = watched([&](const SolverOptions& o) { return solve_jacobi(system, o); }, terms, 1, system,
                             options, "term", 1, system.emission);
  series.name = "Neumann series (Jacobi from B = E)";
  data.runs.push_back(std::move(series));
  std::vector<std::string> present;
  const bool lit = std::any_of(mesh.surfaces.begin(), mesh.surfaces.end(),
                               [](const Surface& s) { return max_component(s.emission) > 0; });
  for (const std::string& lamp : lamps)
    if (lit && std::any_of(mesh.surfaces.begin(), mesh.surfaces.end(), [&](const Surface& s) { return s.name == lamp; }))
      present.push_back(lamp);
  data.lights = solve_per_light(system, mesh, present);
  return data;
}

ViewerData gathering_side_by_side(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, const std::vector<Color>& reference, int iterations,
                                  double omega, double exposure) {
  ViewerData data = viewer_data(lesson, "Jacobi, Gauss-Seidel and SOR side by side, iteration by iteration", mesh,
                                scene.camera, exposure);
  const SolverOptions options = against(reference);
  const auto run = [&](const Solve& solve) {
    data.runs.push_back(watched(solve, iterations, 3, system, options, "iteration", 1, system.emission));
  };
  run([&](const SolverOptions& o) { return solve_jacobi(system, o); });
  run([&](const SolverOptions& o) { return solve_gauss_seidel(system, o); });
  run([&](const SolverOptions& o) { return solve_gauss_seidel(system, o, omega); });
  return data;
}

ViewerData southwell_side_by_side(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                                  const RadiositySystem& system, const std::vector<Color>& reference, int sweeps,
                                  double exposure) {
  ViewerData data = viewer_data(lesson, "Southwell beside Jacobi and Gauss-Seidel at equal work", mesh, scene.camera,
                                exposure);
  const SolverOptions options = against(reference);
  const int n = system.size();
  data.runs.push_back(watched([&](const SolverOptions& o) { return solve_southwell(system, o); }, sweeps * n, 3,
                              system, options, "step", 1.0 / n, std::vector<Color>(n, Color(0.0))));
  data.runs.push_back(watched([&](const SolverOptions& o) { return solve_jacobi(system, o); }, sweeps, 3, system,
                              options, "iteration", 1, system.emission));
  data.runs.push_back(watched([&](const SolverOptions& o) { return solve_gauss_seidel(system, o); }, sweeps, 3, system,
                              options, "iteration", 1, system.emission));
  return data;
}

ViewerData progressive_replay(const std::string& lesson, const RadiosityScene& scene, const Mesh& mesh,
                              const RadiositySystem& system, const ShooterRow& row, int shots, double exposure) {
  ViewerData data = viewer_data(lesson, "Progressive refinement replayed shot by shot", mesh, scene.camera, exposure);
  SolverOptions options;
  options.tolerance = 0;
  options.max_steps = shots;
  const int frames = frames_within(frame_bytes, system.size());
  data.runs.push_back(record_progressive(system, mesh, row, options, frame_steps(shots, frames)));
  return data;
}

ViewerData finished_runs(const std::string& lesson, const std::string& title, const RadiosityScene& scene,
                         const Mesh& mesh, const std::vector<SolverResult>& results, double exposure) {
  ViewerData data = viewer_data(lesson, title, mesh, scene.camera, exposure);
  const double n = static_cast<double>(mesh.elements.size());
  for (const SolverResult& r : results) {
    // A sweep is n^2 multiply-adds: one iteration, or n steps of Southwell or shooting.
    const bool per_element = r.method == "Southwell" || r.method == "progressive";
    data.runs.push_back(finished_run(r, per_element ? "step" : "iteration", per_element ? 1 / n : 1));
  }
  return data;
}

}  // namespace gi
