#include "gi/viewer/recording.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gi/radiosity/system/solvers.hpp"

namespace gi {

namespace {

bool all_finite(const std::vector<Color>& B) {
  return std::all_of(B.begin(), B.end(), [](const Color& c) { return is_finite(c); });
}

bool kept(const std::vector<int>& steps, int step) { return std::binary_search(steps.begin(), steps.end(), step); }

}  // namespace

std::vector<int> frame_steps(int last, int max_frames) {
  std::vector<int> steps;
  const int first = last <= max_frames ? last : std::max(1, max_frames / 2);
  for (int k = 1; k <= first; ++k) steps.push_back(k);
  const int spread = std::max(1, max_frames - first);
  for (int i = 1; first < last && i <= spread; ++i) {
    const int step = first + static_cast<int>(std::lround(double(last - first) * i / spread));
    if (step > steps.back()) steps.push_back(step);
  }
  return steps;
}

int frames_within(std::size_t bytes, int elements) {
  const std::size_t frame = 12 * static_cast<std::size_t>(std::max(1, elements));
  return static_cast<int>(std::clamp<std::size_t>(bytes / frame, 2, 400));
}

ViewerRun record_run(const Solve& solve, SolverOptions options, const std::vector<int>& steps, const std::string& unit,
                     double work_per_step, const std::vector<Color>& start) {
  ViewerRun run;
  run.unit = unit;
  run.work_per_step = work_per_step;
  if (!start.empty()) run.frames.push_back({0, start});
  options.record_every = 1;
  options.observer = [&](const SolverStep& step, const std::vector<Color>& B, const std::vector<Color>&) {
    if (kept(steps, step.step) && all_finite(B)) run.frames.push_back({step.step, B});
  };
  const SolverResult result = solve(options);
  run.name = result.method;
  run.status = stop_reason(result, unit);
  run.history = result.history;
  return run;
}

ViewerRun record_progressive(const RadiositySystem& system, const Mesh& mesh, const ShooterRow& row,
                             SolverOptions options, const std::vector<int>& steps) {
  ViewerRun run;
  run.unit = "shot";
  run.work_per_step = 1.0 / system.size();  // a shot reads one row of n form factors
  run.shooters = true;
  run.frames.push_back({0, system.emission, -1, ambient_term(system.area, system.rho, system.emission)});
  std::vector<Color> before = system.emission;  // the unshot radiosity before this step's shot
  options.record_every = 1;
  options.observer = [&](const SolverStep& step, const std::vector<Color>& B, const std::vector<Color>& unshot) {
    const int shooter = choose_shooter(mesh.patches, system.area, before);
    before = unshot;
    if (kept(steps, step.step) && all_finite(B))
      run.frames.push_back({step.step, B, shooter, ambient_term(system.area, system.rho, unshot)});
  };
  const SolverResult result = solve_progressive(system, mesh, row, options);
  run.name = result.method;
  run.status = stop_reason(result, "shot");
  run.history = result.history;
  return run;
}

ViewerRun finished_run(const SolverResult& result, const std::string& unit, double work_per_step, int max_rows) {
  ViewerRun run;
  run.name = result.method;
  run.unit = unit;
  run.status = stop_reason(result, unit);
  run.work_per_step = work_per_step;
  const std::size_t rows = result.history.size(), every = (rows + max_rows - 1) / std::max(1, max_rows);
  for (std::size_t i = 0; i < rows; ++i)
    if (i % std::max<std::size_t>(every, 1) == 0 || i + 1 == rows) run.history.push_back(result.history[i]);
  if (!result.history.empty() && all_finite(result.B)) run.frames.push_back({result.history.back().step, result.B});
  return run;
}

std::vector<ViewerLight> solve_per_light(const RadiositySystem& system, const Mesh& mesh,
                                         const std::vector<std::string>& lamps) {
  std::vector<std::pair<std::string, std::vector<Color>>> sources;  // name, E of that light alone
  Color brightest(0.0);
  for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
    const Color& e = mesh.surfaces[s].emission;
    if (max_component(e) <= 0) continue;
    if (max_component(e) > max_component(brightest)) brightest = e;
    std::vector<Color> E(system.size(), Color(0.0));
    for (int i = 0; i < system.size(); ++i)
      if (mesh.elements[i].surface == static_cast<int>(s)) E[i] = e;
    sources.emplace_back(mesh.surfaces[s].name, std::move(E));
  }
  const std::size_t scene_lights = sources.size();
  if (!lamps.empty() && scene_lights == 0)
    throw std::invalid_argument("relighting: no surface emits, so a lamp has no exitance to take");
  for (const std::string& lamp : lamps) {
    const auto s = std::find_if(mesh.surfaces.begin(), mesh.surfaces.end(), [&](const Surface& x) { return x.name == lamp; });
    if (s == mesh.surfaces.end()) throw std::invalid_argument("relighting: no surface is called '" + lamp + "'");
    std::vector<Color> E(system.size(), Color(0.0));
    for (int i = 0; i < system.size(); ++i)
      if (mesh.elements[i].surface == static_cast<int>(s - mesh.surfaces.begin())) E[i] = brightest;
    sources.emplace_back(lamp + " as a lamp", std::move(E));
  }
  RadiositySystem lit = system;  // the same form factors for every light
  SolverOptions options;
  options.tolerance = 1e-10;
  std::vector<ViewerLight> lights;
  for (std::size_t l = 0; l < sources.size(); ++l) {
    lit.emission = sources[l].second;
    SolverResult result = solve_gauss_seidel(lit, options);
    if (result.status != SolveStatus::Converged)
      throw std::runtime_error("relighting: the solution for " + sources[l].first + " " + stop_reason(result, "sweep"));
    lights.push_back({sources[l].first, l < scene_lights ? 1.0 : 0.0, std::move(lit.emission), std::move(result.B)});
  }
  return lights;
}

}  // namespace gi
