#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchical_solver.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/solver.hpp"

namespace gi {

// One way to solve a radiosity scene from start to finish -- a mesh, form factors,
// where the direct light comes from, a solver -- so that lessons 12 and 15 can set
// every method side by side on one scene, timed the same way.
// Hierarchical: no uniform mesh at all -- Hanrahan et al.'s quadtrees and links
// (hierarchical/hierarchical_solver.hpp), its leaves the mesh of the result.
enum class RecipeSolver { Direct, Jacobi, GaussSeidel, Southwell, Progressive, Hierarchical };
std::string name(RecipeSolver solver);  // "direct", "Jacobi", "Gauss-Seidel", "Southwell", "progressive", "hierarchical"

struct Recipe {
  int elements = 1000;       // about how many elements (patch_size_for)
  int elements_per_side = 1;  // each patch cut into n x n elements: progressive refinement shoots from
                              // patches; the matrix solvers use elements only
  FormFactorSettings form_factors;  // the interreflection's (and, without exact_direct, all light's);
                                    // hemicube_resolution 0: chosen from the mesh (hemicube_resolution_for)
  bool exact_direct = true;         // the first bounce by direct_radiosity, the rest by form_factors
  DirectLightSettings direct;
  RecipeSolver solver = RecipeSolver::GaussSeidel;
  double tolerance = 1e-5;  // the solver's (options.tolerance)
  // RecipeSolver::Hierarchical only: its thresholds. elements, elements_per_side and
  // form_factors are then unused; exact_direct, direct and tolerance are handed to it.
  HierarchicalSettings hierarchical;
};

// "exact direct + hemicube indirect, Gauss-Seidel": what a table row calls the recipe
// (the hemicube's resolution and the ray count go in a column of their own).
std::string describe(const Recipe& recipe);

struct RecipeResult {
  Mesh mesh;  // Hierarchical: its leaves (leaf_mesh.hpp; for display without cracks, leaf_vertex_radiosity)
  std::vector<Color> B;
  std::vector<Color> direct;      // D, exact_direct only: B - E - D is what bounced more than once
  SolveStatus status = SolveStatus::StoppedAtLimit;
  FormFactorSettings form_factors;  // as used: the hemicube's resolution filled in
  HemicubeMatrixStats hemicube;     // receivers smaller than a hemicube cell, over the rows computed
  double form_factor_seconds = 0;  // the matrix (for progressive: the rows, as they are shot; hierarchical: refinement)
  double direct_seconds = 0;       // direct_radiosity (0 without exact_direct)
  double solve_seconds = 0;        // the solver, form factors excluded
  // Hierarchical: the hierarchy and its links, element k being leaves(*hierarchy)[k], for
  // the final gather (link_gather.hpp).
  std::shared_ptr<const Hierarchy> hierarchy;
  double seconds() const { return form_factor_seconds + direct_seconds + solve_seconds; }
};

// The most elements a matrix solver takes: its n x n matrix of doubles is 3.2 GB at 20 000.
inline constexpr int max_matrix_elements = 20000;

// The recipe's work (form factors, direct light, hierarchical refinement) is shared
// among `threads` threads (0 = all cores); the answer is the same for any number.
// Throws std::invalid_argument for bad settings (as make_mesh, check(FormFactorSettings)
// and check(DirectLightSettings) do) and for a matrix solver asked for more than
// max_matrix_elements; asked for up to that, its mesh has about `elements` but never
// more than max_matrix_elements (patch_size_at_most), checked before any work.
RecipeResult solve_recipe(const std::vector<Surface>& surfaces, const Recipe& recipe, int threads);

// A receiver whose image is smaller than one hemicube cell gets a whole cell's dF or
// nothing: its form factor is aliased. A few such receivers average out; when in some row
// more than `hemicube_aliasing_limit` of the cells fall to them, hemicube_warning returns
// one line saying so (the resolution, the worst row's share, how many got no cell at
// all), for a lesson to print under its table; otherwise "".
inline constexpr double hemicube_aliasing_limit = 0.01;
std::string hemicube_warning(const RecipeResult& result);

// The hemicube resolution for a mesh: cells small enough that an element a scene's
// size away still covers two and a half across, 2.5 * 2 L / s with s the mean element's
// side and L the scene's bounding-box diagonal over sqrt(3) (the top face is 2 wide at
// distance 1), rounded up to even, at least 100 and at most 1000. Two across left 1.3%
// of the worst row's cells to receivers smaller than a cell on the Cornell box at 4 300
// elements, past hemicube_aliasing_limit; two and a half stays under it.
int hemicube_resolution_for(const Mesh& mesh);

}  // namespace gi
