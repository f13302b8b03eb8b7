#pragma once
#include <cstddef>
#include <vector>

#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/hierarchical/refine.hpp"
#include "gi/radiosity/system/solver.hpp"

namespace gi {

// Hierarchical radiosity, the whole algorithm (Hanrahan, Salzman and Aupperle 1991):
//   1. link the surfaces with F-refinement;
//   2. solve: gather over the links, push-pull, again, until B changes by less than
//      the tolerance;
//   3. refine the links against that B (BF-refinement); if none changed, stop,
//      else solve again (2), starting from the B that is there.
struct HierarchicalSettings {
  RefinementSettings refinement;
  double tolerance = 1e-6;  // each solve: until ||B_new - B_old|| / ||E|| (leaves, area-weighted) is below it
  int max_iterations = 500; // per solve
  int max_rounds = 20;      // BF-refinements after the first round
  // Exact direct light, as lesson 12's recipes have it (direct_light.hpp): every leaf's
  // D = rho (1/A) integral of H(x) over it, by shadow rays to the light, and the links
  // carry only the light that has bounced: the nodes hold B' of
  //   B'_p = D_p + rho_p sum over links F V B'_q        (indirect_system's equation)
  // and the result adds E back, B = E + B'. The oracle then refines for the smooth
  // indirect light only; the shadows are the direct light's business.
  bool exact_direct = false;
  DirectLightSettings direct;
};
void check(const HierarchicalSettings& settings);  // throws std::invalid_argument

// One round: a refinement and the solve after it.
struct RefinementRound {
  int round = 0;  // 0: F-refinement; 1, 2 ...: BF-refinement
  int nodes = 0, leaves = 0;
  std::size_t links = 0;
  std::size_t evaluated = 0;  // candidate links judged (each an F, F_back and V)
  std::size_t replaced = 0;   // links of earlier rounds the oracle refined
  int iterations = 0;         // of the solve
  double refine_seconds = 0, solve_seconds = 0;
  // How much the solve moved B, over the leaves: sqrt(sum A (B - B_before)^2 / sum A B^2)
  // (channels summed), B_before what the leaves held before it (a new leaf its parent's).
  double change = 0;
};

struct HierarchicalResult {
  // B per leaf, in the order of leaves(hierarchy); the history holds every iteration of
  // every round, numbered on, its time counting the refinements too. Converged when the
  // last refinement changed nothing and the solve before it converged.
  SolverResult solution;
  std::vector<Color> direct;  // exact_direct only: D per leaf; solution.B - E - D is what bounced more than once
  std::vector<RefinementRound> rounds;
};

// Step 2 alone, on the links as they are: gather (every node, in parallel) then
// push-pull, from the nodes' current B, until options.tolerance (on residual_2) or
// options.max_steps. A step's residual is B_new - B_old = E + (gather, push)(B_old) -
// B_old at the leaves, its norms weighted by the leaves' areas; options.reference, if
// given, holds one B per leaf. The nodes keep the final B. Same B for any thread count.
SolverResult solve_links(Hierarchy& hierarchy, const SolverOptions& options, int threads);

// The whole algorithm, on a hierarchy fresh from make_hierarchy (or with links: then
// step 1 is skipped and it refines what is there). `blockers` holds the input
// surfaces' polygons (the shadow rays' world).
HierarchicalResult solve_hierarchical(Hierarchy& hierarchy, const FormFactorScene& blockers,
                                      const HierarchicalSettings& settings, int threads);

// B of every leaf, in the order of leaves().
std::vector<Color> leaf_radiosity(const Hierarchy& hierarchy);

}  // namespace gi
