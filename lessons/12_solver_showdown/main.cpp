// Lesson 12 -- every solver on the same Cornell box, in one table and one chart; the
// cases where solvers crawl or fail; float against double; how fine a mesh the box
// needs; and how close a Gauss-Seidel sweep comes to the memory's speed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/core/timer.hpp"
#include "gi/image/metrics.hpp"
#include "gi/radiosity/display.hpp"
#include "gi/radiosity/float_sweep.hpp"
#include "gi/radiosity/progressive.hpp"
#include "gi/radiosity/radiosity_scenes.hpp"
#include "gi/radiosity/solvers.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

struct Box {
  gi::Mesh mesh;
  gi::RadiositySystem system;
};

// A scene meshed into about `elements` elements, with its hemicube form factors.
Box meshed(const gi::RadiosityScene& scene, int elements, int threads, double* ff_ms = nullptr) {
  gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
  const gi::Timer timer;
  gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), {}, threads));
  if (ff_ms) *ff_ms = timer.milliseconds();
  return {std::move(mesh), std::move(system)};
}

Box cornell(int elements, bool closed, int threads, double* ff_ms = nullptr) {
  return meshed(gi::cornell_box(closed), elements, threads, ff_ms);
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
}

// 2. Where solvers crawl or fail, and the spectral radius of RF that says how fast
// they go: Jacobi's error shrinks by rho(RF) per iteration, so it needs about
// ln(1e-6) / ln rho(RF) of them. rho(RF) is measured (power iteration, the largest over
// the channels), not assumed: it equals the reflectance only in a room that is truly
// closed, like the empty box; the Cornell box's "closed" front leaves floor elements
// under the blocks that see nothing and absorb all they get.
void stability(const Box& closed, const Box& open, const Box& empty, gi::Lesson& lesson) {
  gi::Table table("Stability: iterations to ||r|| < 1e-6 (at most 20 000), or the failure detected",
                  {{"case"}, {"rho(RF)", 4}, {"ln(1e-6)/ln rho", 0}, {"Jacobi"}, {"Jacobi steps"}, {"Gauss-Seidel"},
                   {"G-S steps"}});
  const auto run = [&](const std::string& name, const gi::RadiositySystem& s) {
    double radius = 0;
    for (int channel = 0; channel < 3; ++channel) radius = std::max(radius, gi::spectral_radius(s, channel).value());
    gi::SolverOptions options;
    options.tolerance = 1e-6;
    options.max_steps = 20000;
    const gi::SolverResult j = gi::solve_jacobi(s, options), g = gi::solve_gauss_seidel(s, options);
    const gi::Cell predicted = radius < 1 ? gi::Cell(std::log(1e-6) / std::log(radius)) : gi::Cell("-");
    table.add_row({name, radius, predicted, gi::status_name(j.status), j.history.back().step,
                   gi::status_name(g.status), g.history.back().step});
  };
  const auto with_rho = [](gi::RadiositySystem s, double rho) {
    for (gi::Color& r : s.rho) r = gi::Color(rho);
    return s;
  };
  run("Cornell reflectances, closed", closed.system);
  run("Cornell reflectances, open front", open.system);
  for (double rho : {0.9, 0.99, 0.999})
    run("empty closed box, all rho = " + gi::format_number(rho, 3, gi::Format::Fixed), with_rho(empty.system, rho));
  run("Cornell closed, all rho = 0.999", with_rho(closed.system, 0.999));
  run("Cornell open front, all rho = 0.99", with_rho(open.system, 0.99));
  run("all rho = 1.05 (unphysical)", with_rho(closed.system, 1.05));
  gi::RadiositySystem rows = with_rho(closed.system, 0.95);
  for (double& f : rows.F.values) f *= 1.1;  // rows summing to 1.1: energy from nowhere
  run("rho = 0.95, F rows sum to 1.1", rows);
  lesson.table(table, "stability");
}

// 3. Float against double: where each one's residual stops falling.
void precision(const Box& box, gi::Lesson& lesson) {
  const gi::RadiositySystem& s = box.system;
  gi::FloatSystem f{s.size(), std::vector<float>(s.F.values.begin(), s.F.values.end()), {}, {}};
  for (int i = 0; i < s.size(); ++i)
    for (int c = 0; c < 3; ++c) f.rho.push_back(float(s.rho[i][c])), f.emission.push_back(float(s.emission[i][c]));
  std::vector<float> Bf(f.emission.begin(), f.emission.end());
  std::vector<gi::Color> Bd = s.emission;
  gi::Table table("Gauss-Seidel in float and in double: relative residual per sweep",
                  {{"sweep"}, {"float", 2, gi::Format::Scientific}, {"double", 2, gi::Format::Scientific}});
  for (int sweep = 1; sweep <= 30; ++sweep) {
    gi::gauss_seidel_sweep_float(f, Bf);
    gi::gauss_seidel_sweep(s, Bd);
    if (sweep % 3 == 0) {
      const std::vector<gi::Color> r = gi::residual(s, Bd);
      double r2 = 0, e2 = 0;
      for (int i = 0; i < s.size(); ++i) r2 += gi::length_squared(r[i]), e2 += gi::length_squared(s.emission[i]);
      table.add_row({sweep, gi::relative_residual(f, Bf), std::sqrt(r2 / e2)});
    }
  }
  lesson.table(table, "precision");
}

// 4. How fine a mesh does the box need? Pictures against the finest mesh's.
void mesh_resolution(int threads, std::uint64_t seed, gi::Lesson& lesson) {
  const gi::RadiosityScene scene = gi::cornell_box();
  gi::DisplaySettings display;
  display.width = display.height = 96;
  display.threads = threads;
  display.seed = seed;
  const auto picture = [&](const Box& box, const gi::SolverResult& r) {
    return gi::render_radiosity(gi::FormFactorScene(gi::element_shapes(box.mesh)), box.mesh, r.B, scene.camera, display);
  };
  gi::SolverOptions options;
  options.tolerance = 1e-6;
  std::vector<int> sizes = {50, 100, 200, 400, 800, 1600, 3200};
  const Box finest = cornell(sizes.back(), false, threads);
  const gi::Image reference = picture(finest, gi::solve_gauss_seidel(finest.system, options));
  gi::Table table("Mesh resolution: time and picture error against " + std::to_string(finest.system.size()) +
                      " elements (smooth shading, 96x96)",
                  {{"elements"}, {"form factors ms", 0}, {"solve ms", 1}, {"picture RMSE", 2, gi::Format::Scientific}});
  gi::Series curve{"meshes", {}, {}};
  sizes.pop_back();
  for (int n : sizes) {
    double ff_ms = 0;
    const Box box = cornell(n, false, threads, &ff_ms);
    const gi::SolverResult r = gi::solve_gauss_seidel(box.system, options);
    const double error = gi::rmse(picture(box, r), reference);
    table.add_row({box.system.size(), ff_ms, 1e3 * r.history.back().seconds, error});
    curve.x.push_back(ff_ms + 1e3 * r.history.back().seconds), curve.y.push_back(error);
  }
  lesson.table(table, "mesh_resolution");
  lesson.chart({"Mesh resolution: picture error against time", "form factors + solve (ms)", "RMSE of the picture",
                true, true, {curve}},
               "mesh_error_vs_time");
}

// 5. One Gauss-Seidel sweep over an n x n float matrix against the memory's speed.
void bandwidth(int n, gi::Lesson& lesson) {
  gi::FloatSystem s{n, std::vector<float>(static_cast<std::size_t>(n) * n), std::vector<float>(3 * n, 0.5f),
                    std::vector<float>(3 * n)};
  gi::Rng rng(12);
  for (float& f : s.F) f = static_cast<float>(2.0 / n * rng.uniform());  // rows sum to about 1, like a closed room
  for (float& e : s.emission) e = static_cast<float>(rng.uniform());
  std::vector<float> B(s.emission);
  const double bytes = 4.0 * n * n;
  std::vector<double> read, sweep;
  float sink = 0;
  for (int run = 0; run < 3; ++run) {
    gi::Timer timer;
    sink += gi::sum_all(s.F);  // the bound: just read every form factor
    read.push_back(timer.seconds());
    timer.restart();
    gi::gauss_seidel_sweep_float(s, B);
    sweep.push_back(timer.seconds());
  }
  const double bound = bytes / gi::median(read) / 1e9, achieved = bytes / gi::median(sweep) / 1e9;
  gi::Table table("One Gauss-Seidel sweep over a dense " + std::to_string(n) + " x " + std::to_string(n) +
                      " float matrix (" + gi::format_number(bytes / 1e6, 0, gi::Format::Fixed) + " MB), one thread, median of 3",
                  {{"pass"}, {"ms", 1}, {"GB/s", 2}, {"x the bound", 2}});
  table.add_row({"read every F_ij (the memory-bandwidth bound)", 1e3 * gi::median(read), bound, 1.0});
  table.add_row({"Gauss-Seidel sweep, 3 channels", 1e3 * gi::median(sweep), achieved, gi::median(sweep) / gi::median(read)});
  lesson.table(table, "bandwidth");
  if (!std::isfinite(sink)) std::cout << "(checksum " << sink << ")\n";  // keeps the read from being optimised away
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("12_solver_showdown", "All radiosity solvers on one Cornell box; where they crawl or fail; "
                                          "float against double; mesh resolution; a sweep against memory speed.");
  int elements = 400, bandwidth_n = 10000;
  bool skip_mesh = false;
  lesson.options()
      .add("--elements", elements, "about how many elements for the showdown and stability tables", 20, 3000)
      .add("--bandwidth-n", bandwidth_n, "size n of the n x n float matrix of the sweep benchmark", 100, 20000)
      .add_flag("--skip-mesh-study", skip_mesh, "leave out the mesh-resolution table (the slowest part)");
  return lesson.run(argc, argv, [&] {
    const Box open = cornell(elements, false, lesson.threads()), closed = cornell(elements, true, lesson.threads());
    showdown(open, lesson);
    std::cout << '\n';
    stability(closed, open, meshed(gi::closed_box(1.0), 150, lesson.threads()), lesson);
    std::cout << '\n';
    precision(closed, lesson);
    if (!skip_mesh) {
      std::cout << '\n';
      mesh_resolution(lesson.threads(), lesson.seed(), lesson);
    }
    std::cout << '\n';
    bandwidth(bandwidth_n, lesson);
    lesson.say("\ntables and charts: " + lesson.out().string() + "/");
  });
}
