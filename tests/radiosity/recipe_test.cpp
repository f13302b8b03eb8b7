// solve_recipe's account of the hemicube: receivers smaller than a cell are counted in
// the rows that see them, by the matrix solvers and by shooting alike, and a hemicube
// too coarse for its mesh is named in one warning line.
#include <gtest/gtest.h>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/recipe.hpp"

namespace {

gi::Recipe hemicube_recipe(int elements, int resolution, gi::RecipeSolver solver) {
  gi::Recipe r;
  r.elements = elements;
  r.exact_direct = false;
  r.form_factors.hemicube_resolution = resolution;
  r.solver = solver;
  return r;
}

TEST(RecipeHemicube, ACoarseHemicubeOnAFineMeshIsWarnedAbout) {
  const gi::RadiosityScene box = gi::cornell_box();
  for (gi::RecipeSolver solver : {gi::RecipeSolver::GaussSeidel, gi::RecipeSolver::Progressive}) {
    const gi::RecipeResult r = gi::solve_recipe(box.surfaces, hemicube_recipe(1000, 20, solver), 0);
    EXPECT_GT(r.hemicube.sub_cell_missed, 0) << name(solver);
    EXPECT_GE(r.hemicube.sub_cell_receivers, r.hemicube.sub_cell_missed) << name(solver);
    EXPECT_GT(r.hemicube.rows_with_sub_cell_receivers, 0) << name(solver);
    EXPECT_GT(r.hemicube.worst_sub_cell_share, gi::hemicube_aliasing_limit) << name(solver);
    EXPECT_LT(r.hemicube.worst_sub_cell_share, 1) << name(solver);
    const std::string warning = gi::hemicube_warning(r);
    EXPECT_EQ(warning.rfind("warning: hemicube 20: ", 0), 0u) << warning;
    EXPECT_NE(warning.find(std::to_string(r.hemicube.sub_cell_missed) + " got none"), std::string::npos) << warning;
  }
}

// The share falls as the cells shrink: a receiver's image covers more of them.
TEST(RecipeHemicube, AFinerHemicubeAliasesLess) {
  const gi::RadiosityScene box = gi::cornell_box();
  double last = 1;
  for (int resolution : {20, 60, 200}) {
    const gi::RecipeResult r =
        gi::solve_recipe(box.surfaces, hemicube_recipe(300, resolution, gi::RecipeSolver::GaussSeidel), 0);
    EXPECT_LT(r.hemicube.worst_sub_cell_share, last) << "resolution " << resolution;
    last = r.hemicube.worst_sub_cell_share;
    if (resolution == 200) {
      EXPECT_EQ(gi::hemicube_warning(r), "");
    }
  }
}

// The resolution chosen from the mesh is the one the warning accepts, at a mesh fine
// enough that it is above the floor of 100.
TEST(RecipeHemicube, TheResolutionChosenFromTheMeshIsNotWarnedAbout) {
  const gi::RadiosityScene box = gi::cornell_box();
  gi::Recipe recipe = hemicube_recipe(4000, 0, gi::RecipeSolver::Progressive);
  recipe.elements_per_side = 3;
  const gi::RecipeResult r = gi::solve_recipe(box.surfaces, recipe, 0);
  EXPECT_GT(r.form_factors.hemicube_resolution, 100);
  EXPECT_EQ(r.form_factors.hemicube_resolution, gi::hemicube_resolution_for(r.mesh));
  EXPECT_EQ(gi::hemicube_warning(r), "");
}

TEST(RecipeHemicube, OtherMethodsHaveNoCellsToAlias) {
  const gi::RadiosityScene box = gi::cornell_box();
  gi::Recipe r = hemicube_recipe(300, 100, gi::RecipeSolver::GaussSeidel);
  r.form_factors.method = gi::FormFactorMethod::MonteCarlo;
  r.form_factors.rays = 64;
  const gi::RecipeResult result = gi::solve_recipe(box.surfaces, r, 0);
  EXPECT_EQ(result.hemicube.sub_cell_receivers, 0);
  EXPECT_EQ(result.hemicube.worst_sub_cell_share, 0);
  EXPECT_EQ(gi::hemicube_warning(result), "");
}

}  // namespace

// Past the stored matrix's limit a matrix solver is refused before any work (the
// mesh of up to the limit is capped at it: mesh_test.cpp).
TEST(Recipe, AMatrixSolverPastItsLimitIsRefusedAtOnce) {
  gi::Recipe recipe;
  recipe.elements = gi::max_matrix_elements + 1;
  try {
    (void)gi::solve_recipe(gi::cornell_box().surfaces, recipe, 0);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "solve_recipe: 20001 elements is too many for a stored matrix (at most 20000)");
  }
}
