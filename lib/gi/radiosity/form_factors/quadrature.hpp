#pragma once
#include <functional>
#include <vector>

#include "gi/core/wide_float.hpp"

namespace gi {

// The n-point Gauss-Legendre rule on [0, 1]: exact for polynomials of degree 2n - 1.
// Computed once per order (1..64) and kept, so asking is free after the first time.
struct GaussRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};
const GaussRule& gauss_legendre(int order);  // throws std::invalid_argument outside 1..64

// An integral with the error estimate that came with it.
struct Estimate {
  double value = 0;
  double error = 0;
  int evaluations = 0;
};

// One piece of a sum of one-dimensional integrals: the integral of f over [a, b].
// In gi::wide (long double, a 64-bit mantissa on x86-64; double on Apple silicon and
// with MSVC), for sums whose pieces cancel in part.
struct Integrand {
  std::function<wide(wide)> f;
  wide a;
  wide b;
};

// The sum of the pieces' integrals by adaptive Gauss-Kronrod quadrature (Piessens
// et al., QUADPACK): each interval gets the 15-point Kronrod rule, and the difference
// from the 7-point Gauss rule nested in it is its error estimate. The interval with
// the largest estimate, over all pieces, is halved until the estimates add up to
// less than max(relative_tolerance * |sum|, the round-off of the sum) or
// max_evaluations is reached. Intervals shrink towards whatever makes an integrand
// hard -- a logarithmic singularity at an end, a sharp bend -- and nowhere else.
Estimate integrate_adaptive(const std::vector<Integrand>& pieces, double relative_tolerance, int max_evaluations);

}  // namespace gi
