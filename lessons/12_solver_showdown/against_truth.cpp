// Lesson 12, step 4: every method against the path-traced truth (against_truth.hpp).
#include "against_truth.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/radiosity/recipe_picture.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/table.hpp"

namespace lesson12 {
namespace {

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

}  // namespace

void against_truth(Study study, const gi::Truth& truth, int threads, std::uint64_t seed, gi::Lesson& lesson) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const int size = 256;
  const gi::BlockMask mask = gi::interior_blocks(scene.surfaces, scene.camera, size, size, 8);
  const gi::PictureError noise = gi::reference_noise(truth.standard_error, truth.mean, mask);
  gi::DisplaySettings display;
  display.width = display.height = size;
  const gi::View view{scene.camera, size, size, gi::describe_pixel_samples(display)};
  gi::Table table("The Cornell box against the path-traced truth (" + std::to_string(truth.spp) + " spp, whose own " +
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
    const gi::PictureError error = gi::picture_error(picture, truth.mean, mask);
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
  lesson.picture(truth.mean, "cornell_path_traced", "the path-traced truth (lessons/references/)", view, 2);
}

}  // namespace lesson12
