#pragma once
// Stratified (jittered) sampling: cut the domain into N strata of equal size and draw
// one uniform point in each. The estimate stays unbiased, and its variance is the mean
// of the strata's own variances over N instead of the whole domain's: for a smooth
// integrand over the square with N = n x n strata, f varies by O(1/n) across a stratum,
//   Var = N * O(1/n^2) / N^2 = O(N^-2)                      RMS error ~ N^-1,
// and for an integrand with a jump along a curve only the O(n) strata the curve crosses
// keep a variance of O(1):
//   Var = O(n) / N^2 = O(N^-3/2)                            RMS error ~ N^-3/4
// (in d dimensions N^(-1/2 - 1/d) smooth, N^(-1/2 - 1/(2d)) with a jump: the gain
// fades as d grows). Mitchell, "Consequences of stratified sampling in graphics",
// SIGGRAPH 1996; pbrt-v4, section 8.5.
//
// A path tracer asks for sample i of a pixel's N, in any order, for each decision of a
// path. If sample i sat in stratum i of every decision, the decisions would move
// together (the pixel's left edge would always see the light's left edge); so each
// decision d draws its own random permutation pi_d and sample i takes stratum pi_d(i).
#include <cstdint>

#include "gi/core/math.hpp"

namespace gi {

// N strata of the square as an nx x ny grid: nx the largest divisor of N with
// nx <= sqrt(N), so a square N (the case the error laws above are for) gives n x n,
// N = 8 gives 2 x 4, and a prime N gives 1 x N (stratified along y only).
struct StrataGrid {
  std::uint32_t nx = 1;
  std::uint32_t ny = 1;
};
// Throws std::invalid_argument for N = 0.
StrataGrid strata_grid(std::uint32_t n);

// Element i of a random permutation of [0, n) (i < n), the permutation chosen by seed.
std::uint32_t permutation_element(std::uint32_t i, std::uint32_t n, std::uint64_t seed);

// The point of stratum s (< n) of [0, 1) cut into n strata, moved by the jitter j, a
// uniform 32-bit integer:  x = (s + j 2^-32) / n.
double jittered_1d(std::uint32_t stratum, std::uint32_t n, std::uint32_t jitter);

// The point of stratum s (< nx ny) of the square: column s mod nx, row s / nx, moved
// within its cell by two jitters:  (((s mod nx) + jx 2^-32) / nx, ((s / nx) + jy 2^-32) / ny).
vec2 jittered_2d(std::uint32_t stratum, StrataGrid grid, std::uint32_t jitter_x, std::uint32_t jitter_y);

}  // namespace gi
