// 12_cornell_bench: one radiosity recipe on the Cornell box, from the input quads to the
// picture, scored against the stored path-traced truth -- so that the time a recipe needs
// for a given error can be measured as a whole process (start-up, reading the reference
// and scoring included), as lesson 12's table cannot. Not a lesson. For example, the
// recipe lesson 12 finds nearest 2% at the lowest cost:
//   12_cornell_bench --elements 2000 --ff monte-carlo --direct per-pixel
// or lesson 13's hierarchical radiosity, which needs no --elements (its picture gathers
// what bounced over the links at the end, link_gather.hpp):
//   12_cornell_bench --solver hierarchical --threshold 1e-3 --min-area 3e-4 --order 2
// prints one line: the recipe, elements, seconds from the quads to the picture, and the
// relative RMS error over lesson 12's interior 8 x 8 blocks (percent).
#include <string>

#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/radiosity/recipe_picture.hpp"
#include "gi/report/lesson.hpp"

int main(int argc, char** argv) {
  gi::Lesson lesson("12_cornell_bench", "One radiosity recipe on the Cornell box, timed from the quads to the "
                                        "picture and scored against the path-traced truth.");
  gi::Recipe recipe;
  std::string ff = "hemicube", direct = "per-pixel", solver = "gauss-seidel";
  recipe.direct.light_cells = 4;
  lesson.options()
      .add("--elements", recipe.elements, "about how many elements, the mesh never past the matrix's 20 000", 20,
           gi::max_matrix_elements)
      .add("--ff", ff, "form factors of the interreflection", {"hemicube", "monte-carlo"})
      .add("--rays", recipe.form_factors.rays, "Monte Carlo's rays per row", 1, 1 << 20)
      .add("--resolution", recipe.form_factors.hemicube_resolution,
           "the hemicube's resolution, 0: chosen from the mesh", 0, 2000)
      .add("--direct", direct, "where the direct light comes from: drawn per pixel, exact on the mesh, or the "
                               "form factors like all light", {"per-pixel", "exact", "form-factors"})
      .add("--light-cells", recipe.direct.light_cells, "the light cut into n x n cells for the direct light", 1, 64)
      .add("--solver", solver, "Gauss-Seidel on a uniform mesh, or hierarchical radiosity (lesson 13: no mesh, "
                               "--elements, --ff, --rays and --resolution unused)", {"gauss-seidel", "hierarchical"})
      .add("--threshold", recipe.hierarchical.refinement.threshold, "hierarchical: BF_eps", 1e-6, 1.0)
      .add("--min-area", recipe.hierarchical.refinement.min_area, "hierarchical: the smallest node's share of the "
                                                                   "scene's area", 1e-7, 0.1)
      .add("--order", recipe.hierarchical.refinement.order, "hierarchical: Gauss points a side of each link's F "
                                                             "(2 is enough where the picture gathers at the end)", 2, 4);
  return lesson.run(argc, argv, [&] {
    const gi::RadiosityScene scene = gi::cornell_box();
    const int size = 256;
    gi::Truth truth = gi::stored_truth(std::string(GI_SOURCE_DIR) + "/lessons/references", "cornell", size, size);
    truth.mask = gi::interior_blocks(scene.surfaces, scene.camera, size, size, 8);

    const gi::Timer timer;
    if (ff == "monte-carlo") recipe.form_factors.method = gi::FormFactorMethod::MonteCarlo;
    if (solver == "hierarchical") recipe.solver = gi::RecipeSolver::Hierarchical;
    recipe.exact_direct = direct != "form-factors";
    const gi::RecipeResult r = gi::solve_recipe(scene.surfaces, recipe, lesson.threads());
    if (r.status != gi::SolveStatus::Converged) throw std::runtime_error("the solver did not converge");
    gi::DisplaySettings display;
    display.width = display.height = size;
    const gi::Image picture = gi::recipe_picture(r, scene.camera, display, direct == "per-pixel", recipe.direct,
                                                lesson.seed(), lesson.threads());
    const double seconds = timer.seconds();

    const gi::PictureError error = gi::score(picture, truth).error;
    const std::string setting =
        recipe.solver == gi::RecipeSolver::Hierarchical
            ? "BF_eps " + gi::format_number(recipe.hierarchical.refinement.threshold, 0, gi::Format::Scientific) +
                  ", min area " + gi::format_number(recipe.hierarchical.refinement.min_area, 0, gi::Format::Scientific) +
                  ", order " + std::to_string(recipe.hierarchical.refinement.order)
        : recipe.form_factors.method == gi::FormFactorMethod::MonteCarlo
            ? std::to_string(recipe.form_factors.rays) + " rays"
            : "resolution " + std::to_string(r.form_factors.hemicube_resolution);
    lesson.say((direct == "per-pixel" ? "direct per pixel, " : "") + gi::describe(recipe) + " (" + setting + "), " +
               std::to_string(r.mesh.elements.size()) + " elements: " +
               gi::format_number(seconds, 2, gi::Format::Fixed) + " s, relative RMS " +
               gi::format_number(100 * error.relative_rms, 2, gi::Format::Fixed) + "% against the path-traced truth");
    if (const std::string w = gi::hemicube_warning(r); !w.empty()) lesson.say(w);
    lesson.picture(picture, "cornell", "the recipe's picture", {scene.camera, size, size,
                                                                 gi::describe_pixel_samples(display)}, 2);
  });
}
