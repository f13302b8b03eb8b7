// Lesson 09 -- gathering: Jacobi (the Neumann series, one bounce per iteration)
// against Gauss-Seidel (the newest values at once) and its over-relaxed variant SOR,
// on the Cornell box, each measured against the direct solution.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/viewer/demos.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

gi::Series curve(const gi::SolverResult& r, bool against_time, bool error) {
  gi::Series s{r.method, {}, {}};
  for (const gi::SolverStep& step : r.history) {
    s.x.push_back(against_time ? 1e3 * step.seconds : step.step);
    s.y.push_back(error ? step.error : step.residual_2);
  }
  return s;
}

// A history cell: the value at `step`, or "-" once the solver has stopped.
gi::Cell at(const gi::SolverResult& r, int step, double gi::SolverStep::*value) {
  const gi::SolverStep* row = gi::find_step(r, step);
  return row ? gi::Cell(row->*value) : gi::Cell("-");
}

// 1. Residual and error of the three solvers, iteration by iteration, for as long
// as any of them ran.
void per_iteration(const std::vector<const gi::SolverResult*>& results, double omega, gi::Lesson& lesson) {
  gi::Table table("Residual ||r||_2 / ||E||_2 and error against the direct solution, per iteration",
                  {{"iteration"}, {"Jacobi r", 2, gi::Format::Scientific}, {"Jacobi error", 2, gi::Format::Scientific},
                   {"G-S r", 2, gi::Format::Scientific}, {"G-S error", 2, gi::Format::Scientific},
                   {"SOR " + gi::format_number(omega, 2, gi::Format::Fixed) + " r", 2, gi::Format::Scientific},
                   {"SOR error", 2, gi::Format::Scientific}});
  int last = 0;
  for (const gi::SolverResult* r : results) last = std::max(last, r->history.back().step);
  for (int k = 1; k <= last; ++k) {
    std::vector<gi::Cell> row{k};
    for (const gi::SolverResult* r : results) {
      row.push_back(at(*r, k, &gi::SolverStep::residual_2));
      row.push_back(at(*r, k, &gi::SolverStep::error));
    }
    table.add_row(row);
  }
  lesson.table(table, "residuals");
  for (const gi::SolverResult* r : results) lesson.say(r->method + ": " + gi::stop_reason(*r, "iteration"));
}

// 2. How much each iteration cuts the error, on average over the first ten (later
// ones reach round-off): the convergence factor, the spectral radius of the
// iteration matrix. It needs two iterations and a non-zero error.
void cost_and_convergence(const std::vector<const gi::SolverResult*>& results, gi::Lesson& lesson) {
  gi::Table cost("Cost and convergence per iteration",
                 {{"solver"}, {"ms per iteration", 3}, {"error factor per iteration", 3}, {"iterations for 1e-6", 0}});
  for (const gi::SolverResult* r : results) {
    const auto& h = r->history;
    const int k = std::min<int>(10, static_cast<int>(h.size()));
    const bool measured = k > 1 && h[0].error > 0 && h[k - 1].error > 0;
    const double factor = measured ? std::pow(h[k - 1].error / h[0].error, 1.0 / (k - 1)) : 0.0;
    const bool converging = measured && factor < 1;
    cost.add_row({r->method, 1e3 * h.back().seconds / h.back().step,
                  measured ? gi::Cell(factor) : gi::Cell("-"),
                  converging ? gi::Cell(std::ceil(std::log(1e-6 / h[0].error) / std::log(factor)) + 1) : gi::Cell("-")});
  }
  std::cout << '\n';
  lesson.table(cost, "cost");
}

// 3. What an iteration does to the picture: the room after 1, 2, 4 and 8 iterations of
// each solver, a row per solver (their errors are rows 1, 2, 4 and 8 of step 1's
// table). Jacobi's k-th picture holds the light of k - 1
// bounces, no more; in Gauss-Seidel's the elements later in a sweep already gather
// the light this sweep gave the earlier ones.
void iteration_grid(const gi::RadiosityScene& scene, const gi::Mesh& mesh, const gi::RadiositySystem& system,
                    gi::SolverOptions settings, double omega, int iterations, gi::Lesson& lesson) {
  std::vector<int> counts;
  for (int k = 1; k <= std::min(iterations, 8); k *= 2) counts.push_back(k);
  std::vector<std::vector<gi::Color>> solutions;
  for (double relax : {0.0, 1.0, omega})  // 0: Jacobi
    for (int k : counts) {
      settings.max_steps = k;
      solutions.push_back(relax == 0 ? gi::solve_jacobi(system, settings).B
                                     : gi::solve_gauss_seidel(system, settings, relax).B);
    }
  std::string after;
  for (int k : counts) after += (after.empty() ? "" : ", ") + std::to_string(k);
  const int columns = static_cast<int>(counts.size());
  const gi::Image grid = gi::solutions_grid(mesh, solutions, columns, scene.camera, 128, lesson.seed(), lesson.threads());
  lesson.diagram(grid, "iterations_grid",
                 "the room after " + after + " iterations (left to right) of Jacobi, Gauss-Seidel and SOR (top to "
                 "bottom); their errors are the per-iteration table's");
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("09_jacobi_gauss_seidel", "Jacobi against Gauss-Seidel and SOR on the Cornell box: residual "
                                              "and error per iteration, against iterations and time.",
                    {.seed = false});
  int elements = 500, iterations = 30, resolution = 100;
  double omega = 1.2;
  lesson.options()
      .add("--elements", elements, "about how many elements to mesh the Cornell box into", 20, 3000)
      .add("--iterations", iterations, "iterations of each solver (fewer if one converges exactly)", 1, 1000)
      .add("--resolution", resolution, "hemicube resolution of the form factors", 10, 1000, gi::even)
      .add("--omega", omega, "SOR relaxation factor", 0.1, 1.95);
  return lesson.run(argc, argv, [&] {
    const gi::RadiosityScene scene = gi::cornell_box();
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const gi::Timer ff_timer;
    const gi::RadiositySystem system =
        gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), resolution, lesson.threads()));
    const double ff_ms = ff_timer.milliseconds();
    const gi::Timer direct_timer;
    const gi::SolverResult direct = gi::solve_direct(system);
    const double direct_ms = direct_timer.milliseconds();
    if (direct.status != gi::SolveStatus::Converged)
      throw std::runtime_error("the direct solution failed: " + gi::stop_reason(direct, "step"));
    lesson.say("Cornell box, " + std::to_string(system.size()) + " elements; form factors (hemicube " +
               std::to_string(resolution) + ") " + gi::format_number(ff_ms, 0, gi::Format::Fixed) +
               " ms; direct solution (Gaussian elimination) " + gi::format_number(direct_ms, 0, gi::Format::Fixed) +
               " ms\n");

    gi::SolverOptions settings;
    settings.tolerance = 0;  // run every iteration: the table compares them step by step
    settings.max_steps = iterations;
    settings.reference = &direct.B;
    const gi::SolverResult jacobi = gi::solve_jacobi(system, settings);
    const gi::SolverResult gauss_seidel = gi::solve_gauss_seidel(system, settings);
    const gi::SolverResult sor = gi::solve_gauss_seidel(system, settings, omega);
    const std::vector<const gi::SolverResult*> results{&jacobi, &gauss_seidel, &sor};

    per_iteration(results, omega, lesson);
    cost_and_convergence(results, lesson);
    iteration_grid(scene, mesh, system, settings, omega, iterations, lesson);

    for (bool error : {false, true}) {
      const std::string what = error ? "error" : "residual";
      lesson.chart({"Jacobi, Gauss-Seidel, SOR: " + what + " against iterations", "iteration",
                    error ? "RMS error / RMS B" : "||r||_2 / ||E||_2", false, true,
                    {curve(jacobi, false, error), curve(gauss_seidel, false, error), curve(sor, false, error)}},
                   what + "_vs_iteration");
      lesson.chart({"Jacobi, Gauss-Seidel, SOR: " + what + " against time", "solver time (ms)",
                    error ? "RMS error / RMS B" : "||r||_2 / ||E||_2", false, true,
                    {curve(jacobi, true, error), curve(gauss_seidel, true, error), curve(sor, true, error)}},
                   what + "_vs_time");
    }
    lesson.viewer("Jacobi, Gauss-Seidel and SOR side by side", [&](const std::filesystem::path& file) {
      gi::write_viewer_data(gi::gathering_side_by_side(lesson.name(), scene, mesh, system, direct.B, iterations, omega),
                            file);
    });
    lesson.say("\ntables and charts: " + lesson.out().string() + "/");
  });
}
