// Lesson 12 -- every solver on the same Cornell box, in one table and one chart; the
// cases where solvers crawl or fail; float against double; every method against the
// path-traced truth; and how close a Gauss-Seidel sweep comes to the memory's speed.
// Step 1 is here; the others are studies of their own, each in its file beside this one.
#include <algorithm>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "against_truth.hpp"
#include "float_matrix.hpp"
#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/system/shooting_furnace.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "gi/viewer/demos.hpp"
#include "stability.hpp"

namespace {

struct Box {
  gi::Mesh mesh;
  gi::RadiositySystem system;
};

// A scene meshed into about `elements` elements, with its hemicube form factors.
Box meshed(const gi::RadiosityScene& scene, int elements, int threads) {
  gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
  gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), {}, threads));
  return {std::move(mesh), std::move(system)};
}

Box cornell(int elements, bool closed, int threads) {
  return meshed(gi::cornell_box(closed), elements, threads);
}

// 1. Every solver, one table, one chart.
void showdown(const Box& box, gi::Lesson& lesson) {
  const gi::RadiositySystem& s = box.system;
  const gi::Timer direct_timer;
  const gi::SolverResult direct = gi::solve_direct(s);
  const double direct_ms = direct_timer.milliseconds();
  if (direct.status != gi::SolveStatus::Converged)
    throw std::runtime_error("the direct solution failed: " + gi::stop_reason(direct, "step"));
  gi::SolverOptions options;
  options.tolerance = 1e-6;
  options.max_steps = 400 * s.size();
  options.reference = &direct.B;
  // Shooting's rows come from the matrix's columns (F_pj = F_jp A_j / A_p) so that it
  // solves the very system the others solve.
  const auto row = [&](int p) {
    std::vector<double> f(s.size());
    for (int j = 0; j < s.size(); ++j) f[j] = s.F(j, p) * s.area[j] / s.area[p];
    return f;
  };
  const std::vector<gi::SolverResult> results = {gi::solve_jacobi(s, options), gi::solve_gauss_seidel(s, options),
                                                 gi::solve_gauss_seidel(s, options, 1.2), gi::solve_southwell(s, options),
                                                 gi::solve_progressive(s, box.mesh, row, options)};
  gi::Table table("All solvers on the Cornell box, " + std::to_string(s.size()) + " elements, to ||r|| < 1e-6 " +
                      "(shooting: unshot energy < 1e-6)",
                  {{"solver"}, {"status"}, {"steps"}, {"sweeps of work", 1}, {"ms", 1},
                   {"error vs direct", 2, gi::Format::Scientific}});
  table.add_row({"direct (Gaussian elimination)", "exact", 1, "-", direct_ms, 0.0});
  std::vector<gi::Series> by_time, by_work;
  for (const gi::SolverResult& r : results) {
    // A sweep is n^2 multiply-adds: one Jacobi or Gauss-Seidel iteration, or n steps of
    // Southwell or shooting.
    const bool per_element = r.method == "Southwell" || r.method == "progressive";
    const double steps_per_sweep = per_element ? s.size() : 1;
    const gi::SolverStep& last = r.history.back();
    table.add_row({r.method, gi::status_name(r.status), last.step, last.step / steps_per_sweep, 1e3 * last.seconds,
                   last.error});
    gi::Series t{r.method, {}, {}}, w{r.method, {}, {}};
    const int every = per_element ? std::max(1, s.size() / 8) : 1;
    for (const gi::SolverStep& step : r.history)
      if (step.step % every == 0) {
        t.x.push_back(1e3 * step.seconds), t.y.push_back(step.error);
        w.x.push_back(step.step / steps_per_sweep), w.y.push_back(step.error);
      }
    by_time.push_back(t), by_work.push_back(w);
  }
  lesson.table(table, "showdown");
  lesson.chart({"All solvers: error against time", "solver time (ms)", "RMS error / RMS B", true, true, by_time},
               "error_vs_time");
  lesson.chart({"All solvers: error against work", "sweeps of work (n^2 multiply-adds)", "RMS error / RMS B", false,
                true, by_work},
               "error_vs_work");
  lesson.viewer("every solver's error curve, values under the pointer", [&](const std::filesystem::path& file) {
    gi::write_viewer_data(gi::finished_runs(lesson.name(), "All solvers on the Cornell box", gi::cornell_box(),
                                            box.mesh, results),
                          file);
  });
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("12_solver_showdown", "All radiosity solvers on one Cornell box; where they crawl or fail; "
                                          "float against double; mesh resolution; a sweep against memory speed.");
  int elements = 400, bandwidth_n = 6000;
  bool skip_mesh = false, quick_truth = false, full_truth = false;
  lesson.options()
      .add("--elements", elements, "about how many elements for the showdown and stability tables", 20, 3000)
      .add("--bandwidth-n", bandwidth_n, "size n of the n x n float matrix of the sweep benchmark (6 000: 144 MB, far past the caches)", 100,
           20000)
      .add_flag("--skip-mesh-study", skip_mesh, "leave out the comparison with the path-traced truth (the slowest part)")
      .add_flag("--quick-mesh-study", quick_truth, "compare only the meshes of up to 500 elements with the truth")
      .add_flag("--full", full_truth, "compare every mesh of docs/12's table with the truth, up to 9 000 elements "
                                      "(under a minute; the default shows seven of its rows)");
  std::optional<gi::Truth> truth;
  lesson.add_check([&] {
    if (int(skip_mesh) + int(quick_truth) + int(full_truth) > 1)
      throw gi::OptionError("--skip-mesh-study, --quick-mesh-study and --full choose how much to compare with the "
                            "truth: give at most one");
    // Before any work: a damaged or stale truth stops the lesson in one line.
    if (!skip_mesh) truth = gi::stored_truth(std::string(GI_SOURCE_DIR) + "/lessons/references", "cornell", 256, 256);
  });
  return lesson.run(argc, argv, [&] {
    const Box open = cornell(elements, false, lesson.threads()), closed = cornell(elements, true, lesson.threads());
    showdown(open, lesson);  // 1. every solver, one table, one chart (above)
    std::cout << '\n';
    // 2. Where solvers crawl or fail (stability.cpp), and where shooting needs reciprocity
    //    (gi/radiosity/system/shooting_furnace.hpp).
    lesson12::stability(closed.system, open.system, meshed(gi::closed_box(1.0), 150, lesson.threads()).system,
                  lesson.threads(), lesson);
    std::cout << '\n';
    lesson.table(gi::shooting_furnace_table(gi::shooting_furnace(150, lesson.threads())), "shooting_furnace");
    std::cout << '\n';
    lesson12::precision(closed.system, lesson);  // 3. float against double (float_matrix.cpp)
    if (!skip_mesh) {
      std::cout << '\n';
      // 4. Every method against the path-traced truth (against_truth.cpp).
      using lesson12::Study;
      const Study study = full_truth ? Study::Full : quick_truth ? Study::Small : Study::Lesson;
      lesson12::against_truth(study, *truth, lesson.threads(), lesson.seed(), lesson);
    }
    std::cout << '\n';
    lesson12::bandwidth(bandwidth_n, lesson);  // 5. a sweep against the memory's speed (float_matrix.cpp)
    lesson.say("\ntables and charts: " + lesson.out().string() + "/");
  });
}
