#pragma once
#include <cstddef>
#include <vector>

namespace gi {

// The radiosity system in single precision, channels side by side, for the two
// questions double precision hides: how fast can a Gauss-Seidel sweep go (it must
// read all n^2 form factors: memory-bound), and how far can float accumulation take
// the residual (about 1e-7 of B, float's epsilon).
struct FloatSystem {
  int n = 0;
  std::vector<float> F;         // n x n, row-major
  std::vector<float> rho;       // 3 per element: r, g, b
  std::vector<float> emission;  // 3 per element
};

// One Gauss-Seidel sweep over B (3 floats per element), in place. The three dot
// products of a row share one read of F_i; `#pragma omp simd` lets the compiler
// vectorise the sums (it may reorder them, so results are exact to float round-off
// only -- the same on every run).
void gauss_seidel_sweep_float(const FloatSystem& system, std::vector<float>& B);

// The sum of every value: one pass reading them all and doing nothing else, the
// memory-bandwidth bound a sweep over the same matrix is measured against.
float sum_all(const std::vector<float>& values);

// ||E + R F B - B||_2 / ||E||_2, accumulated in double.
double relative_residual(const FloatSystem& system, const std::vector<float>& B);

}  // namespace gi
