#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/hierarchical/balance.hpp"
#include "gi/radiosity/hierarchical/refine.hpp"
#include "gi/radiosity/system/solver.hpp"

namespace gi {

// Hierarchical radiosity, the whole algorithm (Hanrahan, Salzman and Aupperle 1991):
//   1. link the surfaces with F-refinement;
//   2. solve: gather over the links, push-pull, again, until B changes little;
//   3. refine the links against that B (BF-refinement); if none changed, go on, else
//      solve again (2), starting from the B that is there;
//   4. balance the links (balance.hpp), so that the light they carry is conserved, and
//      solve once more, to the tolerance.
struct HierarchicalSettings {
  RefinementSettings refinement;
  // The last solve, on the balanced links: until the residual is below it,
  // ||r||_2 / ||source||_2 over the leaves (SolverStep::residual_2, as for every solver).
  // A closed white furnace is then within about the tolerance of its exact B at every leaf.
  double tolerance = 1e-9;
  // The solves between refinements, whose B only judges the links.
  double refining_tolerance = 1e-6;
  int max_iterations = 500; // per solve
  int max_rounds = 20;      // BF-refinements after the first round
  // Exact direct light, as lesson 12's recipes have it (direct_light.hpp): every leaf's
  // D = rho (1/A) integral of H(x) over it, by shadow rays to the light, and the links
  // carry only the light that has bounced: the nodes hold B' of
  //   B'_p = D_p + rho_p sum over links F V B'_q        (indirect_system's equation)
  // with D as their source term (Node::source), and the result adds E back, B = E + B'.
  // The oracle then refines for the smooth indirect light only; the shadows are the
  // direct light's business.
  bool exact_direct = false;
  DirectLightSettings direct;  // its threads are not used: the solve's own thread count splits all the work
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

// Step 4: the balance of the links as they stay, and the solve on them.
struct BalancedSolve {
  Balance balance;
  int iterations = 0;
  double balance_seconds = 0, solve_seconds = 0;
  double change = 0;  // as RefinementRound's: how much the balanced solve moved B
};
// "balanced: 140 of 1537 leaves see only surfaces; their sums 68.5% off, 3e-13 after 19
// sweeps (289 ms); then 21 iterations (496 ms), B moved by 1.0e-02"
std::string describe(const BalancedSolve& balanced);

struct HierarchicalResult {
  // B per leaf, in the order of leaves(hierarchy); the history holds every iteration of
  // every round and of the balanced solve, numbered on, its time counting the
  // refinements too. Converged when the last refinement changed nothing and the
  // balanced solve converged.
  SolverResult solution;
  std::vector<Color> direct;  // exact_direct only: D per leaf; solution.B - E - D is what bounced more than once
  std::vector<RefinementRound> rounds;
  BalancedSolve balanced;
};

// Step 2's solve alone, on the links as they are (and as balanced): gather (every node,
// in parallel) then push-pull, from the nodes' current B, until options.tolerance or
// options.max_steps. The history is SolverMonitor's, as for every solver: step k's row
// is B after k iterations with its residual r = source + T B - B (what one more
// iteration adds), its norms and error over the leaves as Jacobi's over elements;
// options.reference, if given, holds one B per leaf. The nodes keep the final B. Same
// B for any thread count.
SolverResult solve_links(Hierarchy& hierarchy, const SolverOptions& options, int threads);

// The whole algorithm, on a hierarchy fresh from make_hierarchy (or with links: then
// step 1 is skipped and it refines what is there). `blockers` holds the input
// surfaces' polygons (the shadow rays' world).
HierarchicalResult solve_hierarchical(Hierarchy& hierarchy, const FormFactorScene& blockers,
                                      const HierarchicalSettings& settings, int threads);

// B of every leaf, in the order of leaves().
std::vector<Color> leaf_radiosity(const Hierarchy& hierarchy);

}  // namespace gi
