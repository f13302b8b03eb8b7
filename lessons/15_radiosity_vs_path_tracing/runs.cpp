// Lesson 15: every radiosity recipe and path tracing, timed and scored (runs.hpp).
#include "runs.hpp"

#include <stdexcept>

#include "gi/core/timer.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/radiosity/recipe_picture.hpp"
#include "gi/report/progress.hpp"

namespace lesson15 {
namespace {

void score(Run& run, const gi::Truth& truth, const Scoring& scoring) {
  run.error = gi::picture_error(run.picture, truth.mean, scoring.blocks).relative_rms;
  run.pixel_error = gi::picture_error(run.picture, truth.mean, scoring.pixels).relative_rms;
}

// The radiosity recipes: uniform meshes of about `elements` elements; time from the
// scene to the picture (mesh, form factors, direct light, solver, display), as path
// tracing's is.
struct Method {
  std::string family;
  std::vector<int> elements;
  gi::Recipe recipe;
  bool direct_per_pixel = false;
};

std::vector<Method> radiosity_methods(bool full) {
  gi::Recipe all_light;  // lessons 08-11: the hemicube at resolution 100 carries all the light
  all_light.exact_direct = false;
  gi::Recipe monte_carlo_all = all_light, exact_mc, shooting, per_pixel, per_pixel_hemicube;
  monte_carlo_all.form_factors.method = exact_mc.form_factors.method = per_pixel.form_factors.method =
      gi::FormFactorMethod::MonteCarlo;
  monte_carlo_all.form_factors.rays = exact_mc.form_factors.rays = per_pixel.form_factors.rays = 256;
  shooting.solver = gi::RecipeSolver::Progressive;
  shooting.elements_per_side = 3;  // shoot from patches, receive at 3 x 3 elements each
  shooting.form_factors.hemicube_resolution = per_pixel_hemicube.form_factors.hemicube_resolution = 0;  // from the mesh
  per_pixel.direct.light_cells = per_pixel_hemicube.direct.light_cells = 4;  // 2 x 2 eye rays average the rest
  const auto sizes = [&](std::vector<int> quick, std::vector<int> more) {
    if (full) quick.insert(quick.end(), more.begin(), more.end());
    return quick;
  };
  std::vector<Method> list = {
      {"hemicube 100, all light, Gauss-Seidel", sizes({150, 300}, {600, 1200, 2400}), all_light},
      {"Monte Carlo 256, all light, Gauss-Seidel", sizes({300}, {1200}), monte_carlo_all},
      {"exact direct + Monte Carlo, Gauss-Seidel", sizes({300}, {1200, 2400}), exact_mc},
      {"exact direct + hemicube, progressive 3x3", sizes({900}, {2700, 8100}), shooting},
      {"direct per pixel + Monte Carlo, Gauss-Seidel", sizes({150, 300}, {600, 1200, 2400}), per_pixel, true},
      {"direct per pixel + hemicube, Gauss-Seidel", sizes({}, {600, 1200}), per_pixel_hemicube, true},
  };
  // Lesson 13's hierarchical radiosity: no uniform mesh (the elements are its leaves),
  // BF_eps 3e-3 at lesson 13's min area 3e-4, the direct light per pixel as above.
  gi::Recipe hierarchical = per_pixel;
  hierarchical.solver = gi::RecipeSolver::Hierarchical;
  hierarchical.hierarchical.refinement.threshold = 3e-3;
  hierarchical.hierarchical.refinement.min_area = 3e-4;
  list.push_back({"direct per pixel + hierarchical, BF_eps 3e-3", {0}, hierarchical, true});
  return list;
}

}  // namespace

std::vector<Run> solve_radiosity(const gi::RadiosityScene& scene, const Settings& s, const gi::Truth& truth,
                                 const Scoring& scoring) {
  gi::DisplaySettings display;
  display.width = display.height = s.size;
  std::vector<Run> runs;
  for (Method m : radiosity_methods(s.full))
    for (int elements : m.elements) {
      m.recipe.elements = elements;
      const gi::Timer timer;
      const gi::RecipeResult r = gi::solve_recipe(scene.surfaces, m.recipe, s.threads);
      if (r.status != gi::SolveStatus::Converged)
        throw std::runtime_error(m.family + " at " + std::to_string(elements) + " elements did not converge");
      Run run{m.family, m.family, static_cast<int>(r.mesh.elements.size()), 0, 0, 0, {}};
      run.picture = gi::recipe_picture(r, scene.camera, display, m.direct_per_pixel, m.recipe.direct, s.seed, s.threads);
      run.seconds = timer.seconds();
      score(run, truth, scoring);
      runs.push_back(std::move(run));
    }
  return runs;
}

// Path tracing (MIS) at 1, 2, 4, ... spp, one film sampled further for each picture.
std::vector<Run> path_trace(const gi::PathScene& scene, const Settings& s, const gi::Truth& truth,
                            const Scoring& scoring) {
  gi::Film film = gi::make_film(s.size, s.size, s.seed);
  gi::Progress progress("path tracing", s.max_spp);
  std::vector<Run> runs;
  double seconds = 0;
  for (int spp = 1; spp <= s.max_spp; spp *= 2) {
    const gi::Timer timer;
    gi::path_trace(film, scene, {}, spp - static_cast<int>(film.samples), s.threads);
    seconds += timer.seconds();
    progress.advance(spp / 2 + (spp == 1));
    Run run{"path tracing (MIS)", "path tracing (MIS), " + std::to_string(spp) + " spp", 0, seconds, 0, 0, {}};
    run.picture = gi::film_mean(film);
    score(run, truth, scoring);
    runs.push_back(std::move(run));
  }
  progress.finish();
  return runs;
}

}  // namespace lesson15
