// Lesson 09 -- gathering: Jacobi (the Neumann series, one bounce per iteration)
// against Gauss-Seidel (the newest values at once) and its over-relaxed variant SOR,
// on the Cornell box, each measured against the direct solution.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factor_hemicube.hpp"
#include "gi/radiosity/radiosity_scenes.hpp"
#include "gi/radiosity/solvers.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("09_jacobi_gauss_seidel", [&] {
    gi::CommonOptions common;
    int elements = 500, iterations = 30, resolution = 100;
    double omega = 1.2;
    gi::Options options("09_jacobi_gauss_seidel", "Jacobi against Gauss-Seidel and SOR on the Cornell box: residual "
                                                  "and error per iteration, against iterations and time.");
    gi::add_common_options(options, common, "09_jacobi_gauss_seidel");
    options.add("--elements", elements, "about how many elements to mesh the Cornell box into", 20, 3000)
        .add("--iterations", iterations, "iterations of each solver", 1, 1000)
        .add("--resolution", resolution, "hemicube resolution of the form factors (even)", 10, 1000)
        .add("--omega", omega, "SOR relaxation factor", 0.1, 1.95);
    if (!options.parse(argc, argv)) return 0;
    if (resolution % 2) throw gi::OptionError("the hemicube resolution must be even");
    const std::string& out = common.out;

    const gi::RadiosityScene scene = gi::cornell_box();
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const gi::Timer ff_timer;
    const gi::RadiositySystem system =
        gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), resolution, common.threads));
    const double ff_ms = ff_timer.milliseconds();
    const gi::Timer direct_timer;
    const gi::SolverResult direct = gi::solve_direct(system);
    const double direct_ms = direct_timer.milliseconds();
    std::cout << "Cornell box, " << system.size() << " elements; form factors (hemicube " << resolution << ") "
              << gi::format_number(ff_ms, 0, gi::Format::Fixed) << " ms; direct solution (Gaussian elimination) "
              << gi::format_number(direct_ms, 0, gi::Format::Fixed) << " ms\n\n";

    gi::SolverOptions settings;
    settings.tolerance = 0;  // run every iteration: the table compares them step by step
    settings.max_steps = iterations;
    settings.reference = &direct.B;
    const gi::SolverResult jacobi = gi::solve_jacobi(system, settings);
    const gi::SolverResult gauss_seidel = gi::solve_gauss_seidel(system, settings);
    const gi::SolverResult sor = gi::solve_gauss_seidel(system, settings, omega);

    gi::Table table("Residual ||r||_2 / ||E||_2 and error against the direct solution, per iteration",
                    {{"iteration"}, {"Jacobi r", 2, gi::Format::Scientific}, {"Jacobi error", 2, gi::Format::Scientific},
                     {"G-S r", 2, gi::Format::Scientific}, {"G-S error", 2, gi::Format::Scientific},
                     {"SOR " + gi::format_number(omega, 2, gi::Format::Fixed) + " r", 2, gi::Format::Scientific},
                     {"SOR error", 2, gi::Format::Scientific}});
    for (std::size_t k = 0; k < jacobi.history.size(); ++k)
      table.add_row({jacobi.history[k].step, jacobi.history[k].residual_2, jacobi.history[k].error,
                     gauss_seidel.history[k].residual_2, gauss_seidel.history[k].error, sor.history[k].residual_2,
                     sor.history[k].error});
    table.print();
    table.write_csv(out + "/residuals.csv");

    // How much each iteration cuts the error, on average over the first ten (later
    // ones reach round-off): the convergence factor, the spectral radius of the
    // iteration matrix.
    gi::Table cost("Cost and convergence per iteration",
                   {{"solver"}, {"ms per iteration", 3}, {"error factor per iteration", 3}, {"iterations for 1e-6", 0}});
    for (const gi::SolverResult* r : {&jacobi, &gauss_seidel, &sor}) {
      const auto& h = r->history;
      const int k = std::min<int>(10, static_cast<int>(h.size()));
      const double factor = k > 1 ? std::pow(h[k - 1].error / h[0].error, 1.0 / (k - 1)) : 0.0;
      cost.add_row({r->method, 1e3 * h.back().seconds / h.size(), factor,
                    factor > 0 && factor < 1 ? std::ceil(std::log(1e-6 / h[0].error) / std::log(factor)) + 1 : NAN});
    }
    std::cout << '\n';
    cost.print();

    for (bool error : {false, true}) {
      const std::string what = error ? "error" : "residual";
      gi::write_svg({"Jacobi, Gauss-Seidel, SOR: " + what + " against iterations", "iteration",
                     error ? "RMS error / RMS B" : "||r||_2 / ||E||_2", false, true,
                     {curve(jacobi, false, error), curve(gauss_seidel, false, error), curve(sor, false, error)}},
                    out + "/" + what + "_vs_iteration.svg");
      gi::write_svg({"Jacobi, Gauss-Seidel, SOR: " + what + " against time", "solver time (ms)",
                     error ? "RMS error / RMS B" : "||r||_2 / ||E||_2", false, true,
                     {curve(jacobi, true, error), curve(gauss_seidel, true, error), curve(sor, true, error)}},
                    out + "/" + what + "_vs_time.svg");
    }
    std::cout << "\ntables and charts: " << out << "/\n";
    return 0;
  });
}
