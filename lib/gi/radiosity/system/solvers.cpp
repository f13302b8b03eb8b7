#include "gi/radiosity/system/solvers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

SolverResult solve_direct(const RadiositySystem& s, const SolverOptions& options) {
  SolverMonitor monitor("direct", s, options);
  const int n = s.size();
  std::vector<Color> B(n);
  for (int channel = 0; channel < 3; ++channel) {
    // K = I - R F, augmented with E, eliminated to upper triangular form.
    std::vector<double> K(static_cast<std::size_t>(n) * (n + 1));
    const auto k = [&](int i, int j) -> double& { return K[static_cast<std::size_t>(i) * (n + 1) + j]; };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) k(i, j) = (i == j) - s.rho[i][channel] * s.F(i, j);
      k(i, n) = s.emission[i][channel];
    }
    // Singular where a pivot is round-off of the matrix's size: a closed room whose
    // every surface reflects all it receives (rho = 1, rows of F summing to 1) gives
    // pivots of 1e-15, not 0, and dividing by them made a B of 1e15 that was not an
    // answer. An honest nearly singular room (rho = 0.999999) has pivots of 1e-6.
    double largest = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) largest = std::max(largest, std::abs(k(i, j)));
    const double negligible = 1e-12 * n * largest;
    for (int column = 0; column < n; ++column) {
      int pivot = column;  // the largest entry below, for stability
      for (int i = column + 1; i < n; ++i)
        if (std::abs(k(i, column)) > std::abs(k(pivot, column))) pivot = i;
      if (!(std::abs(k(pivot, column)) > negligible)) return monitor.fail(SolveStatus::Singular, 1);
      for (int j = column; j <= n; ++j) std::swap(k(column, j), k(pivot, j));
      for (int i = column + 1; i < n; ++i) {
        const double factor = k(i, column) / k(column, column);
        if (factor != 0)
          for (int j = column; j <= n; ++j) k(i, j) -= factor * k(column, j);
      }
    }
    for (int i = n - 1; i >= 0; --i) {  // back substitution
      double sum = k(i, n);
      for (int j = i + 1; j < n; ++j) sum -= k(i, j) * B[j][channel];
      B[i][channel] = sum / k(i, i);
    }
  }
  monitor.stop_after(1, B);
  return monitor.finish(std::move(B));
}

void jacobi_iteration(const RadiositySystem& s, const std::vector<Color>& B_old, std::vector<Color>& B_new) {
  // BEGIN EXERCISE 9.1 one Jacobi iteration
  const int n = s.size();
  for (int i = 0; i < n; ++i) {
    Color gathered(0.0);
    for (int j = 0; j < n; ++j) gathered += s.F(i, j) * B_old[j];
    B_new[i] = s.emission[i] + s.rho[i] * gathered;
  }
  // END EXERCISE 9.1
}

SolverResult solve_jacobi(const RadiositySystem& s, const SolverOptions& options) {
  SolverMonitor monitor("Jacobi", s, options);
  std::vector<Color> B = s.emission, next(s.size());
  for (int iteration = 1;; ++iteration) {
    jacobi_iteration(s, B, next);
    std::swap(B, next);
    if (monitor.stop_after(iteration, B)) break;
  }
  return monitor.finish(std::move(B));
}

void gauss_seidel_sweep(const RadiositySystem& s, std::vector<Color>& B, double omega) {
  // BEGIN EXERCISE 9.2 one Gauss-Seidel sweep
  const int n = s.size();
  for (int i = 0; i < n; ++i) {
    Color gathered(0.0);
    for (int j = 0; j < n; ++j) gathered += s.F(i, j) * B[j];  // B[j < i] are already new
    const Color gauss_seidel = s.emission[i] + s.rho[i] * gathered;
    B[i] = (1 - omega) * B[i] + omega * gauss_seidel;
  }
  // END EXERCISE 9.2
}

SolverResult solve_gauss_seidel(const RadiositySystem& s, const SolverOptions& options, double omega) {
  if (!(omega > 0 && omega < 2)) throw std::invalid_argument("SOR: omega must lie in (0, 2)");
  SolverMonitor monitor(omega == 1 ? "Gauss-Seidel" : "SOR", s, options);
  std::vector<Color> B = s.emission;
  for (int sweep = 1;; ++sweep) {
    gauss_seidel_sweep(s, B, omega);
    if (monitor.stop_after(sweep, B)) break;
  }
  return monitor.finish(std::move(B));
}

int southwell_step(const RadiositySystem& s, std::vector<Color>& B, std::vector<Color>& r) {
  // BEGIN EXERCISE 10.1 a Southwell step with the incremental residual update
  const int n = s.size();
  int i = 0;
  for (int j = 1; j < n; ++j)
    if (max_component(glm::abs(r[j])) > max_component(glm::abs(r[i]))) i = j;
  const Color relaxed = r[i];
  B[i] += relaxed;
  r[i] = Color(0.0);
  for (int j = 0; j < n; ++j)
    if (j != i) r[j] += s.rho[j] * s.F(j, i) * relaxed;  // column i: what j gathers from i
  return i;
  // END EXERCISE 10.1
}

SolverResult solve_southwell(const RadiositySystem& s, const SolverOptions& options) {
  SolverMonitor monitor("Southwell", s, options);
  std::vector<Color> B(s.size(), Color(0.0)), r = s.emission;  // B = 0: r = E
  for (int step = 1;; ++step) {
    southwell_step(s, B, r);
    if (monitor.stop_after(step, B, r)) break;
  }
  return monitor.finish(std::move(B), std::move(r));
}

}  // namespace gi
