#include "gi/radiosity/system/float_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "gi/core/not_implemented.hpp"

namespace gi {

void gauss_seidel_sweep_float(const FloatSystem& s, std::vector<float>& B) {
  const std::size_t n = static_cast<std::size_t>(s.n);
  // B stored as three planes, so that each dot product runs over contiguous floats.
  std::vector<float> planes(3 * n);
  float *r = planes.data(), *g = r + n, *b = g + n;
  for (std::size_t j = 0; j < n; ++j) r[j] = B[3 * j], g[j] = B[3 * j + 1], b[j] = B[3 * j + 2];
  // Rows in blocks of four: one pass over B serves four rows (B is read from cache a
  // quarter as often, and twelve independent sums keep the adders busy). Rows later
  // in the block must see the values just computed before them, as Gauss-Seidel
  // demands: they gathered the old ones, and are corrected by F_ik (new - old).
  constexpr std::size_t block = 4;
  for (std::size_t i0 = 0; i0 < n; i0 += block) {
    const std::size_t rows = std::min(block, n - i0);
    float sr[block] = {}, sg[block] = {}, sb[block] = {};
    if (rows == block) {
      const float* f0 = s.F.data() + i0 * n;
      const float *f1 = f0 + n, *f2 = f1 + n, *f3 = f2 + n;
      float r0 = 0, g0 = 0, b0 = 0, r1 = 0, g1 = 0, b1 = 0, r2 = 0, g2 = 0, b2 = 0, r3 = 0, g3 = 0, b3 = 0;
#pragma omp simd reduction(+ : r0, g0, b0, r1, g1, b1, r2, g2, b2, r3, g3, b3)
      for (std::size_t j = 0; j < n; ++j) {
        const float x = r[j], y = g[j], z = b[j];
        r0 += f0[j] * x, g0 += f0[j] * y, b0 += f0[j] * z;
        r1 += f1[j] * x, g1 += f1[j] * y, b1 += f1[j] * z;
        r2 += f2[j] * x, g2 += f2[j] * y, b2 += f2[j] * z;
        r3 += f3[j] * x, g3 += f3[j] * y, b3 += f3[j] * z;
      }
      sr[0] = r0, sr[1] = r1, sr[2] = r2, sr[3] = r3;
      sg[0] = g0, sg[1] = g1, sg[2] = g2, sg[3] = g3;
      sb[0] = b0, sb[1] = b1, sb[2] = b2, sb[3] = b3;
    } else {  // the last few rows, one at a time
      for (std::size_t k = 0; k < rows; ++k) {
        const float* row = s.F.data() + (i0 + k) * n;
        float ar = 0, ag = 0, ab = 0;
#pragma omp simd reduction(+ : ar, ag, ab)
        for (std::size_t j = 0; j < n; ++j) ar += row[j] * r[j], ag += row[j] * g[j], ab += row[j] * b[j];
        sr[k] = ar, sg[k] = ag, sb[k] = ab;
      }
    }
    for (std::size_t k = 0; k < rows; ++k) {
      const std::size_t i = i0 + k;
      for (std::size_t m = 0; m < k; ++m) {  // the rows of this block already updated
        const float f = s.F[i * n + i0 + m];
        sr[k] += f * (r[i0 + m] - B[3 * (i0 + m)]);
        sg[k] += f * (g[i0 + m] - B[3 * (i0 + m) + 1]);
        sb[k] += f * (b[i0 + m] - B[3 * (i0 + m) + 2]);
      }
      r[i] = s.emission[3 * i] + s.rho[3 * i] * sr[k];
      g[i] = s.emission[3 * i + 1] + s.rho[3 * i + 1] * sg[k];
      b[i] = s.emission[3 * i + 2] + s.rho[3 * i + 2] * sb[k];
    }
    for (std::size_t k = 0; k < rows; ++k) {  // B keeps the old values until the block is done
      const std::size_t i = i0 + k;
      B[3 * i] = r[i], B[3 * i + 1] = g[i], B[3 * i + 2] = b[i];
    }
  }
}

float sum_all(const std::vector<float>& values) {
  float sum = 0;
#pragma omp simd reduction(+ : sum)
  for (std::size_t k = 0; k < values.size(); ++k) sum += values[k];
  return sum;
}

double relative_residual(const FloatSystem& s, const std::vector<float>& B) {
  // BEGIN EXERCISE 12.2 the relative residual of a float solution, summed in double
  const std::size_t n = static_cast<std::size_t>(s.n);
  double r2 = 0, e2 = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      double gathered = 0;
      for (std::size_t j = 0; j < n; ++j) gathered += double(s.F[i * n + j]) * B[3 * j + c];
      const double r = s.emission[3 * i + c] + s.rho[3 * i + c] * gathered - B[3 * i + c];
      r2 += r * r, e2 += double(s.emission[3 * i + c]) * s.emission[3 * i + c];
    }
  return std::sqrt(r2 / (e2 > 0 ? e2 : 1));
  // END EXERCISE 12.2
}

}  // namespace gi
