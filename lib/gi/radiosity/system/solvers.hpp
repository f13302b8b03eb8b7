#pragma once
#include "gi/radiosity/system/solver.hpp"

namespace gi {

// Solvers of (I - R F) B = E over a stored form-factor matrix. Each returns the same
// SolverResult (solver.hpp); progressive refinement, which stores no matrix, is in
// progressive.hpp.

// Gaussian elimination with partial pivoting, per colour channel: O(n^3) time and
// O(n^2) memory, exact to round-off. The reference for small meshes; it does not
// scale, which is why the iterative methods exist. A singular K (a zero pivot) gives
// the status Singular, B all NaN and one history row.
SolverResult solve_direct(const RadiositySystem& system, const SolverOptions& options = {});

// One Jacobi iteration: every element gathers from the previous iterate only,
//   B_new_i = E_i + rho_i sum_j F_ij B_old_j
// Started from B = E, k iterations sum the Neumann series E + RFE + ... + (RF)^k E:
// light after k bounces.
void jacobi_iteration(const RadiositySystem& system, const std::vector<Color>& B_old, std::vector<Color>& B_new);
SolverResult solve_jacobi(const RadiositySystem& system, const SolverOptions& options = {});

// One Gauss-Seidel sweep, in place: element i gathers from the newest values, those
// of elements < i already updated in this sweep. With omega != 1 it is successive
// over-relaxation: B_i <- (1 - omega) B_i + omega * (the Gauss-Seidel value).
void gauss_seidel_sweep(const RadiositySystem& system, std::vector<Color>& B, double omega = 1.0);
SolverResult solve_gauss_seidel(const RadiositySystem& system, const SolverOptions& options = {}, double omega = 1.0);

// One Southwell step: pick the element i with the largest residual (max over
// channels of |r_i|), relax it -- B_i += r_i, which zeroes r_i since F_ii = 0 -- and
// update every other residual incrementally, r_j += rho_j F_ji r_i: O(n), not the
// O(n^2) of recomputing r. Returns i.
int southwell_step(const RadiositySystem& system, std::vector<Color>& B, std::vector<Color>& r);
SolverResult solve_southwell(const RadiositySystem& system, const SolverOptions& options = {});

}  // namespace gi
