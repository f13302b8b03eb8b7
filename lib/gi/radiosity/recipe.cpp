#include "gi/radiosity/recipe.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "gi/core/timer.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/system/solvers.hpp"

namespace gi {

std::string name(RecipeSolver solver) {
  switch (solver) {
    case RecipeSolver::Direct: return "direct";
    case RecipeSolver::Jacobi: return "Jacobi";
    case RecipeSolver::GaussSeidel: return "Gauss-Seidel";
    case RecipeSolver::Southwell: return "Southwell";
    case RecipeSolver::Progressive: return "progressive";
    case RecipeSolver::Hierarchical: return "hierarchical";
  }
  return "?";
}

std::string describe(const Recipe& r) {
  const std::string ff = r.solver == RecipeSolver::Hierarchical ? "links" : name(r.form_factors.method);
  const std::string light = r.exact_direct ? "exact direct + " + ff + " indirect" : ff + " for all light";
  return light + ", " + name(r.solver);
}

std::string hemicube_warning(const RecipeResult& result) {
  const HemicubeMatrixStats& s = result.hemicube;
  if (s.worst_sub_cell_share <= hemicube_aliasing_limit) return "";
  char share[32];
  std::snprintf(share, sizeof share, "%.1f%%", 100 * s.worst_sub_cell_share);
  return "warning: hemicube " + std::to_string(result.form_factors.hemicube_resolution) + ": in the worst row " +
         share + " of the cells fall to receivers smaller than a cell, each given a whole cell or none (" +
         std::to_string(s.sub_cell_missed) + " got none, over " + std::to_string(s.rows_with_sub_cell_receivers) +
         " rows): raise the resolution or coarsen the mesh";
}

int hemicube_resolution_for(const Mesh& mesh) {
  double area = 0;
  vec3 lo(1e300), hi(-1e300);
  for (const Element& e : mesh.elements) {
    area += e.shape.area;
    for (const vec3& c : e.shape.corners) lo = min(lo, c), hi = max(hi, c);
  }
  const double side = std::sqrt(area / double(mesh.elements.size())), size = length(hi - lo) / std::sqrt(3.0);
  const int cells = static_cast<int>(std::ceil(2.5 * 2 * size / side));
  return std::clamp(cells + cells % 2, 100, 1000);
}

namespace {

SolverResult run_solver(const RadiositySystem& system, const Mesh& mesh, const ShooterRow& row, const Recipe& r) {
  SolverOptions options;
  options.tolerance = r.tolerance;
  options.max_steps = r.solver == RecipeSolver::Southwell || r.solver == RecipeSolver::Progressive
                          ? 1000 * system.size()
                          : 100000;
  options.record_every = r.solver == RecipeSolver::Southwell ? std::max(1, system.size() / 4) : 1;
  switch (r.solver) {
    case RecipeSolver::Direct: return solve_direct(system, options);
    case RecipeSolver::Jacobi: return solve_jacobi(system, options);
    case RecipeSolver::GaussSeidel: return solve_gauss_seidel(system, options);
    case RecipeSolver::Southwell: return solve_southwell(system, options);
    case RecipeSolver::Progressive: return solve_progressive(system, mesh, row, options);
    case RecipeSolver::Hierarchical: break;  // solve_recipe hands it to hierarchical_recipe
  }
  throw std::invalid_argument("solve_recipe: unknown solver");
}

// Hierarchical radiosity from start to finish: refinement counts as its form
// factors, the solves as its solver, the rest of its clock as the direct light.
RecipeResult hierarchical_recipe(const std::vector<Surface>& surfaces, const Recipe& r, int threads) {
  HierarchicalSettings settings = r.hierarchical;
  settings.exact_direct = r.exact_direct;
  settings.direct = r.direct;
  settings.tolerance = r.tolerance;
  const Timer timer;
  HierarchicalRun run = run_hierarchical({"", surfaces, {}}, settings, threads);
  RecipeResult result;
  for (const RefinementRound& round : run.result.rounds)
    result.form_factor_seconds += round.refine_seconds, result.solve_seconds += round.solve_seconds;
  result.form_factor_seconds += run.result.balanced.balance_seconds;  // the links' balance is part of making them
  result.solve_seconds += run.result.balanced.solve_seconds;
  result.direct_seconds = r.exact_direct ? std::max(0.0, timer.seconds() - result.form_factor_seconds -
                                                             result.solve_seconds)
                                         : 0.0;
  result.mesh = leaf_mesh(run.hierarchy).mesh;
  result.hierarchy = std::make_shared<const Hierarchy>(std::move(run.hierarchy));
  result.B = std::move(run.result.solution.B);
  result.direct = std::move(run.result.direct);
  result.status = run.result.solution.status;
  result.form_factors = r.form_factors;
  return result;
}

}  // namespace

RecipeResult solve_recipe(const std::vector<Surface>& surfaces, const Recipe& recipe, int threads) {
  if (recipe.solver == RecipeSolver::Hierarchical) return hierarchical_recipe(surfaces, recipe, threads);
  RecipeResult result;
  const bool shooting = recipe.solver == RecipeSolver::Progressive;
  if (!shooting && recipe.elements > max_matrix_elements)
    throw std::invalid_argument("solve_recipe: " + std::to_string(recipe.elements) + " elements is too many for a " +
                                "stored matrix (at most " + std::to_string(max_matrix_elements) + ")");
  // A matrix solver's mesh is about `elements`, but never past the matrix's limit.
  const int most = shooting ? 1'000'000 : max_matrix_elements;
  result.mesh = make_mesh(surfaces, {patch_size_at_most(surfaces, recipe.elements, recipe.elements_per_side, most),
                                     recipe.elements_per_side});
  const Mesh& mesh = result.mesh;
  Recipe r = recipe;
  if (r.form_factors.method == FormFactorMethod::Hemicube && r.form_factors.hemicube_resolution == 0)
    r.form_factors.hemicube_resolution = hemicube_resolution_for(mesh);
  check(r.form_factors);
  if (r.exact_direct) check(r.direct);
  result.form_factors = r.form_factors;
  const FormFactorScene receivers(element_shapes(mesh));
  Timer timer;
  RadiositySystem system = make_system(
      mesh, shooting ? FormFactorMatrix{} : form_factor_matrix(receivers, r.form_factors, threads, &result.hemicube));
  result.form_factor_seconds = timer.seconds();

  timer.restart();
  const std::vector<Color> E = system.emission;
  if (r.exact_direct) {
    result.direct = direct_radiosity(receivers, mesh, r.direct, threads);
    system = indirect_system(std::move(system), result.direct);  // moved, not copied: F may be 100s of MB
  }
  result.direct_seconds = r.exact_direct ? timer.seconds() : 0;

  // Shooting computes a patch's row the first time it shoots and keeps it: those
  // seconds are the form factors', the rest the solver's.
  std::vector<std::vector<double>> rows(mesh.patches.size());
  double row_seconds = 0;
  const ShooterRow row = [&](int p) {
    if (rows[p].empty()) {
      const Timer row_timer;
      FormFactorRow shot = form_factor_row_with_diagnostics(receivers, mesh.patches[p].shape, p, r.form_factors);
      row_seconds += row_timer.seconds();
      rows[p] = std::move(shot.F);
      result.hemicube.add_row(shot.sub_cell_receivers, shot.sub_cell_missed, shot.sub_cell_share);
    }
    return rows[p];
  };
  const SolverResult solution = run_solver(system, mesh, row, r);
  // The solver's own clock leaves out the monitor's bookkeeping (residuals for the
  // history), which is not part of the method.
  result.solve_seconds = solution.history.back().seconds - row_seconds;
  result.form_factor_seconds += row_seconds;
  result.status = solution.status;
  result.B = solution.B;
  if (r.exact_direct)
    for (std::size_t i = 0; i < E.size(); ++i) result.B[i] += E[i];  // B = E + B_indirect
  return result;
}

}  // namespace gi
