// Lesson 10 -- Southwell: relax only the element with the largest residual, and
// update the other residuals incrementally in O(n). Compared with Jacobi and
// Gauss-Seidel by the work done (one sweep = n^2 multiply-adds = n Southwell steps)
// and by time.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/viewer/demos.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

// Error against work in sweeps (an iteration is one sweep, a Southwell step 1/n) or
// against time; a point every `every` steps keeps the chart light (Southwell's, a quarter
// sweep apart, draws markers that stay apart).
gi::Series curve(const gi::SolverResult& r, double steps_per_sweep, bool against_time, int every) {
  gi::Series s{r.method, {}, {}};
  for (const gi::SolverStep& step : r.history)
    if (step.step % every == 0) {
      s.x.push_back(against_time ? 1e3 * step.seconds : step.step / steps_per_sweep);
      s.y.push_back(step.error);
    }
  return s;
}

// A history cell: the error at `step`, or "-" if the solver stopped before it.
gi::Cell error_at(const gi::SolverResult& r, int step) {
  const gi::SolverStep* row = gi::find_step(r, step);
  return row ? gi::Cell(row->error) : gi::Cell("-");
}

// 1. Southwell's residual and error, n/8 steps apart, then every n, for the steps
// that ran.
void southwell_table(const gi::SolverResult& southwell, int n, int sweeps, gi::Lesson& lesson) {
  gi::Table table("Southwell: residual and error against the direct solution (n/8 steps apart, then n)",
                  {{"step"}, {"sweeps of work", 3}, {"||r||_2", 2, gi::Format::Scientific},
                   {"max |r_i|", 2, gi::Format::Scientific}, {"unshot energy", 2, gi::Format::Scientific},
                   {"error", 2, gi::Format::Scientific}});
  std::vector<int> shown;
  for (int k = 1; k < 8; ++k) shown.push_back(k * n / 8);
  for (int k = 1; k <= sweeps; ++k) shown.push_back(k * n);
  for (int step : shown)
    if (const gi::SolverStep* s = gi::find_step(southwell, step))
      table.add_row({s->step, double(s->step) / n, s->residual_2, s->residual_inf, s->unshot, s->error});
  lesson.table(table, "southwell");
  lesson.say("Southwell: " + gi::stop_reason(southwell, "step"));
}

// 2. Equal work: k sweeps of Gauss-Seidel against k n Southwell steps.
void equal_work(const gi::SolverResult& jacobi, const gi::SolverResult& gauss_seidel,
                const gi::SolverResult& southwell, int n, int sweeps, gi::Lesson& lesson) {
  gi::Table work("Error after equal work, and the cost of one unit of it",
                 {{"sweeps"}, {"Jacobi", 2, gi::Format::Scientific}, {"Gauss-Seidel", 2, gi::Format::Scientific},
                  {"Southwell", 2, gi::Format::Scientific}});
  for (int k = 1; k <= sweeps; k *= 2)
    work.add_row({k, error_at(jacobi, k), error_at(gauss_seidel, k), error_at(southwell, k * n)});
  std::cout << '\n';
  lesson.table(work, "equal_work");
  lesson.say("Jacobi: " + gi::stop_reason(jacobi, "sweep") + "; Gauss-Seidel: " +
             gi::stop_reason(gauss_seidel, "sweep"));
  const double step_us = 1e6 * southwell.history.back().seconds / southwell.history.back().step;
  const double sweep_us = 1e6 * gauss_seidel.history.back().seconds / gauss_seidel.history.back().step;
  // A step reads column i of F, n numbers a row apart: strided, cache-unfriendly
  // reads, which is why a step costs more than 1/n of a sweep.
  lesson.say("\none Southwell step: " + gi::format_number(step_us, 2, gi::Format::Fixed) +
             " us (O(n)); one Gauss-Seidel sweep: " + gi::format_number(sweep_us, 1, gi::Format::Fixed) +
             " us (O(n^2)); ratio " + gi::format_number(sweep_us / step_us, 0, gi::Format::Fixed) + " for n = " +
             std::to_string(n));
}

// 3. Equal work as pictures: the room after 1, 2, 4 and 8 sweeps of work of Jacobi,
// Gauss-Seidel and Southwell (k n steps), a row per solver (their errors are step 2's
// table). Southwell's first steps go to the light and to what
// it lights most: the walls brighten where the light lands before the rest catch up.
void work_grid(const gi::RadiosityScene& scene, const gi::Mesh& mesh, const gi::RadiositySystem& system,
               gi::SolverOptions settings, int sweeps, gi::Lesson& lesson) {
  const int n = system.size();
  std::vector<int> counts;
  for (int k = 1; k <= std::min(sweeps, 8); k *= 2) counts.push_back(k);
  std::vector<std::vector<gi::Color>> solutions;
  for (int solver = 0; solver < 3; ++solver)
    for (int k : counts) {
      settings.max_steps = solver == 2 ? k * n : k;
      solutions.push_back(solver == 0   ? gi::solve_jacobi(system, settings).B
                          : solver == 1 ? gi::solve_gauss_seidel(system, settings).B
                                        : gi::solve_southwell(system, settings).B);
    }
  std::string after;
  for (int k : counts) after += (after.empty() ? "" : ", ") + std::to_string(k);
  const int columns = static_cast<int>(counts.size());
  const gi::Image grid = gi::solutions_grid(mesh, solutions, columns, scene.camera, 128, lesson.seed(), lesson.threads());
  lesson.diagram(grid, "work_grid",
                 "the room after " + after + " sweeps of work (left to right) of Jacobi, Gauss-Seidel and Southwell "
                 "(top to bottom; a sweep of Southwell's is n steps); their errors are the equal-work table's");
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("10_southwell", "Southwell iteration on the Cornell box: residual per step, the cost of a "
                                    "step, and error against work and time beside Jacobi and Gauss-Seidel.",
                    {.seed = false});
  int elements = 500, sweeps = 12, resolution = 100;
  lesson.options()
      .add("--elements", elements, "about how many elements to mesh the Cornell box into", 20, 3000)
      .add("--sweeps", sweeps, "work budget, in sweeps (n Southwell steps each)", 1, 200)
      .add("--resolution", resolution, "hemicube resolution of the form factors", 10, 1000, gi::even);
  return lesson.run(argc, argv, [&] {
    const gi::RadiosityScene scene = gi::cornell_box();
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const gi::RadiositySystem system =
        gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), resolution, lesson.threads()));
    const gi::SolverResult direct = gi::solve_direct(system);
    if (direct.status != gi::SolveStatus::Converged)
      throw std::runtime_error("the direct solution failed: " + gi::stop_reason(direct, "step"));
    const int n = system.size();

    gi::SolverOptions settings;
    settings.tolerance = 0;
    settings.reference = &direct.B;
    settings.max_steps = sweeps * n;
    const gi::SolverResult southwell = gi::solve_southwell(system, settings);  // history: every step
    settings.max_steps = sweeps;
    const gi::SolverResult jacobi = gi::solve_jacobi(system, settings);
    const gi::SolverResult gauss_seidel = gi::solve_gauss_seidel(system, settings);

    lesson.say("Cornell box, " + std::to_string(n) + " elements (hemicube " + std::to_string(resolution) +
               " form factors)\n");
    southwell_table(southwell, n, sweeps, lesson);
    equal_work(jacobi, gauss_seidel, southwell, n, sweeps, lesson);
    work_grid(scene, mesh, system, settings, sweeps, lesson);

    lesson.chart({"Error against work (1 sweep = n^2 multiply-adds = n Southwell steps)", "sweeps of work",
                  "RMS error / RMS B", false, true,
                  {curve(jacobi, 1, false, 1), curve(gauss_seidel, 1, false, 1),
                   curve(southwell, n, false, std::max(1, n / 4))}},
                 "error_vs_work");
    lesson.chart({"Error against time", "solver time (ms)", "RMS error / RMS B", false, true,
                  {curve(jacobi, 1, true, 1), curve(gauss_seidel, 1, true, 1),
                   curve(southwell, n, true, std::max(1, n / 4))}},
                 "error_vs_time");
    lesson.viewer("Southwell beside Jacobi and Gauss-Seidel at equal work", [&](const std::filesystem::path& file) {
      gi::write_viewer_data(gi::southwell_side_by_side(lesson.name(), scene, mesh, system, direct.B, sweeps), file);
    });
    lesson.say("\ntables and charts: " + lesson.out().string() + "/");
  });
}
