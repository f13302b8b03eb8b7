// Lesson 12 -- every solver on the same Cornell box, in one table and one chart; the
// cases where solvers crawl or fail; float against double; every method against the
// path-traced truth; and how close a Gauss-Seidel sweep comes to the memory's speed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/recipe_picture.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/system/float_sweep.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/system/shooting_furnace.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/viewer/demos.hpp"
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
  lesson.viewer("every solver's error curve, values under the pointer", [&](const std::filesystem::path& file) {
    gi::write_viewer_data(gi::finished_runs(lesson.name(), "All solvers on the Cornell box", gi::cornell_box(),
                                            box.mesh, results),
                          file);
  });
}

// 2. Where solvers crawl or fail, and the spectral radius of RF that says how fast
// they go: Jacobi's error shrinks by rho(RF) per iteration, so it needs about
// ln(1e-6) / ln rho(RF) of them. rho(RF) is measured (power iteration, the largest over
// the channels), not assumed: it equals the reflectance only in a room that is truly
// closed, like the empty box; the Cornell box's "closed" front leaves floor elements
// under the blocks that see nothing and absorb all they get.
void stability(const Box& closed, const Box& open, const Box& empty, int threads, gi::Lesson& lesson) {
  const auto with_rho = [](gi::RadiositySystem s, double rho) {
    for (gi::Color& r : s.rho) r = gi::Color(rho);
    return s;
  };
  std::vector<std::pair<std::string, gi::RadiositySystem>> cases = {{"Cornell reflectances, closed", closed.system},
                                                                    {"Cornell reflectances, open front", open.system}};
  for (double rho : {0.9, 0.99, 0.999})
    cases.emplace_back("empty closed box, all rho = " + gi::format_number(rho, 3, gi::Format::Fixed),
                       with_rho(empty.system, rho));
  cases.emplace_back("Cornell closed, all rho = 0.999", with_rho(closed.system, 0.999));
  cases.emplace_back("Cornell open front, all rho = 0.99", with_rho(open.system, 0.99));
  cases.emplace_back("all rho = 1.05 (unphysical)", with_rho(closed.system, 1.05));
  gi::RadiositySystem rows = with_rho(closed.system, 0.95);
  for (double& f : rows.F.values) f *= 1.1;  // rows summing to 1.1: energy from nowhere
  cases.emplace_back("rho = 0.95, F rows sum to 1.1", std::move(rows));

  // Each case's spectral radius, Jacobi and Gauss-Seidel are independent of one
  // another: three tasks per case, shared among the threads (the slow cases near
  // rho = 1 take seconds each), each writing only its own slot.
  const int n = static_cast<int>(cases.size());
  std::vector<double> radius(n);
  std::vector<gi::SolverResult> jacobi(n), gauss_seidel(n);
  gi::SolverOptions options;
  options.tolerance = 1e-6;
  options.max_steps = 20000;
  gi::parallel_for(3 * n, threads, [&](int task) {
    const gi::RadiositySystem& s = cases[task / 3].second;
    if (task % 3 == 0) {
      for (int channel = 0; channel < 3; ++channel)
        radius[task / 3] = std::max(radius[task / 3], gi::spectral_radius(s, channel).value());
    } else if (task % 3 == 1) {
      jacobi[task / 3] = gi::solve_jacobi(s, options);
    } else {
      gauss_seidel[task / 3] = gi::solve_gauss_seidel(s, options);
    }
  });
  gi::Table table("Stability: iterations to ||r|| < 1e-6 (at most 20 000), or the failure detected",
                  {{"case"}, {"rho(RF)", 4}, {"ln(1e-6)/ln rho", 0}, {"Jacobi"}, {"Jacobi steps"}, {"Gauss-Seidel"},
                   {"G-S steps"}});
  for (int c = 0; c < n; ++c) {
    const gi::Cell predicted = radius[c] < 1 ? gi::Cell(std::log(1e-6) / std::log(radius[c])) : gi::Cell("-");
    table.add_row({cases[c].first, radius[c], predicted, gi::status_name(jacobi[c].status),
                   jacobi[c].history.back().step, gi::status_name(gauss_seidel[c].status),
                   gauss_seidel[c].history.back().step});
  }
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

// 4. How fine a mesh, and which method, does the box need? Each method's picture,
// through the box's own camera at 256 x 256, against the converged path-traced
// picture of the same box (lessons/references/, made by 14_make_reference): an
// independent method, so this is an error, not a convergence study. Measured over
// the 8 x 8 blocks that lie on one surface other than the light (picture_error.hpp);
// timed from the mesh to B (form factors, direct light, solver), the picture apart.
struct Method {
  std::string family;
  int elements;
  gi::Recipe recipe;
  bool direct_per_pixel = false;  // the direct light drawn per pixel, the mesh showing the rest (direct_display.hpp)
};

// How much of the study to run: the meshes of up to 500 elements (Small); the rows
// that make the lesson's point in a few seconds (Lesson: a mesh refined, the direct
// light made exact, then drawn per pixel, each on two meshes); or every row of docs/12's table (Full).
enum class Study { Small, Lesson, Full };

std::vector<Method> methods(Study study) {
  gi::Recipe shipped;  // lessons 08-11: the hemicube at resolution 100 carries all the light
  shipped.exact_direct = false;
  gi::Recipe sized = shipped, exact, monte_carlo, shooting, differential = shipped;
  sized.form_factors.hemicube_resolution = exact.form_factors.hemicube_resolution = 0;  // from the mesh
  monte_carlo.form_factors.method = gi::FormFactorMethod::MonteCarlo;
  monte_carlo.form_factors.rays = 256;
  shooting.form_factors.hemicube_resolution = 0;
  shooting.solver = gi::RecipeSolver::Progressive;
  shooting.elements_per_side = 3;  // shoot from patches, receive at 3 x 3 elements each
  differential.form_factors.method = gi::FormFactorMethod::Differential;
  std::vector<Method> list;
  // `sizes`: the full study's meshes; `by_default`: those of them the default run shows.
  const auto add = [&](const std::string& family, std::vector<int> sizes, std::vector<int> by_default,
                       const gi::Recipe& recipe, bool per_pixel = false) {
    for (int n : sizes) {
      const bool shown = study == Study::Full    ? true
                         : study == Study::Small ? n <= 500
                                                 : std::find(by_default.begin(), by_default.end(), n) != by_default.end();
      if (shown) list.push_back({family, n, recipe, per_pixel});
    }
  };
  add("hemicube 100, all light", {250, 500, 1000, 2000}, {250, 500}, shipped);
  add("hemicube sized to the mesh, all light", {4000}, {}, sized);
  add("differential, all light", {250, 1000}, {}, differential);
  add("exact direct + hemicube, Gauss-Seidel", {250, 500, 1000, 2000, 4000}, {}, exact);
  add("exact direct + Monte Carlo 256 rays, Gauss-Seidel", {500, 2000}, {500, 2000}, monte_carlo);
  add("exact direct + hemicube, progressive 3x3", {1000, 4000, 9000}, {1000}, shooting);
  // Per pixel, 4 x 4 light cells: a pixel's shadow is averaged over its 2 x 2 eye rays anyway.
  gi::Recipe per_pixel = exact, per_pixel_mc = monte_carlo;
  per_pixel.direct.light_cells = per_pixel_mc.direct.light_cells = 4;
  add("direct per pixel + hemicube, Gauss-Seidel", {250, 500, 1000, 2000}, {}, per_pixel, true);
  add("direct per pixel + Monte Carlo 256 rays, Gauss-Seidel", {500, 2000}, {500, 2000}, per_pixel_mc, true);
  for (gi::RecipeSolver solver : {gi::RecipeSolver::Jacobi, gi::RecipeSolver::Southwell, gi::RecipeSolver::Direct}) {
    gi::Recipe other = exact;
    other.solver = solver;
    add("exact direct + hemicube, other solvers", {1000}, {}, other);
  }
  return list;
}

void against_truth(Study study, const gi::Truth* truth, int threads, std::uint64_t seed, gi::Lesson& lesson) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const int size = 256;
  const gi::BlockMask mask = gi::interior_blocks(scene.surfaces, scene.camera, size, size, 8);
  const gi::PictureError noise = gi::reference_noise(truth->standard_error, truth->mean, mask);
  gi::DisplaySettings display;
  display.width = display.height = size;
  const gi::View view{scene.camera, size, size, gi::describe_pixel_samples(display)};
  gi::Table table("The Cornell box against the path-traced truth (" + std::to_string(truth->spp) + " spp, whose own " +
                      "noise is " + gi::format_number(100 * noise.relative_rms, 2, gi::Format::Fixed) + "% / " +
                      gi::format_number(100 * noise.block_relative, 2, gi::Format::Fixed) + "%), " +
                      std::to_string(mask.count()) + " interior 8x8 blocks of 256x256, smooth shading",
                  {{"method"}, {"elements"}, {"ff"}, {"form factors s", 2, gi::Format::Fixed}, {"direct s", 2, gi::Format::Fixed},
                   {"solve s", 2, gi::Format::Fixed},
                   {"total s", 2, gi::Format::Fixed}, {"relative RMS %", 2}, {"block relative %", 2}});
  std::vector<gi::Series> curves;
  gi::Image best;
  double best_error = 1e300;
  std::vector<std::string> warnings;
  for (Method m : methods(study)) {
    m.recipe.elements = m.elements;
    const gi::RecipeResult r = gi::solve_recipe(scene.surfaces, m.recipe, threads);
    double seconds = r.seconds(), direct_seconds = r.direct_seconds;
    // Per pixel, the direct light is part of the answer, not just of showing it: the
    // picture's time counts.
    const gi::Timer timer;
    const gi::Image picture = gi::recipe_picture(r, scene.camera, display, m.direct_per_pixel, m.recipe.direct, seed,
                                                 threads);
    if (m.direct_per_pixel) seconds += timer.seconds(), direct_seconds += timer.seconds();
    const gi::PictureError error = gi::picture_error(picture, truth->mean, mask);
    const gi::FormFactorMethod ff = r.form_factors.method;
    const gi::Cell setting = ff == gi::FormFactorMethod::Hemicube     ? gi::Cell(r.form_factors.hemicube_resolution)
                             : ff == gi::FormFactorMethod::MonteCarlo ? gi::Cell(r.form_factors.rays)
                                                                      : gi::Cell("-");
    const std::string name = (m.direct_per_pixel ? "direct per pixel, " : "") + gi::describe(m.recipe);
    if (const std::string w = gi::hemicube_warning(r); !w.empty())
      warnings.push_back(name + ", " + std::to_string(r.mesh.elements.size()) + " elements: " + w);
    table.add_row({name, static_cast<int>(r.mesh.elements.size()), setting, r.form_factor_seconds,
                   direct_seconds, r.solve_seconds, seconds,
                   100 * error.relative_rms, 100 * error.block_relative});
    if (curves.empty() || curves.back().name != m.family) curves.push_back({m.family, {}, {}});
    curves.back().x.push_back(seconds), curves.back().y.push_back(100 * error.relative_rms);
    if (error.relative_rms < best_error) best_error = error.relative_rms, best = picture;
  }
  lesson.table(table, "against_truth");
  lesson.say("ff: the hemicube's resolution (chosen from the mesh where it is not 100) or Monte Carlo's rays per row");
  for (const std::string& w : warnings) lesson.say(w);
  lesson.chart({"The Cornell box against the path-traced truth", "mesh to B (s)", "relative RMS error (%)", true, true,
                curves},
               "truth_error_vs_time");
  lesson.picture(best, "cornell_radiosity_best", "the radiosity solution nearest the truth", view, 2);
  lesson.picture(truth->mean, "cornell_path_traced", "the path-traced truth (lessons/references/)", view, 2);
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
    showdown(open, lesson);
    std::cout << '\n';
    stability(closed, open, meshed(gi::closed_box(1.0), 150, lesson.threads()), lesson.threads(), lesson);
    std::cout << '\n';
    lesson.table(gi::shooting_furnace_table(gi::shooting_furnace(150, lesson.threads())), "shooting_furnace");
    std::cout << '\n';
    precision(closed, lesson);
    if (!skip_mesh) {
      std::cout << '\n';
      against_truth(full_truth ? Study::Full : quick_truth ? Study::Small : Study::Lesson, &*truth, lesson.threads(),
                    lesson.seed(), lesson);
    }
    std::cout << '\n';
    bandwidth(bandwidth_n, lesson);
    lesson.say("\ntables and charts: " + lesson.out().string() + "/");
  });
}
