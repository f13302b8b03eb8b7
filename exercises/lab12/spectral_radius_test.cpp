// Graded tests of exercise 12.1: the spectral radius of R F by power iteration. One
// point per test. Every expectation is an eigenvalue known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gi/radiosity/system/radiosity_system.hpp"
#include "support/print.hpp"

using gi::Color;

namespace {

// n elements, all of reflectance rho, each seeing every other one equally: row sums
// `row`, so R F = rho * row * (the averaging matrix), spectral radius rho * row.
gi::RadiositySystem closed_room(int n, double rho, double row = 1.0) {
  gi::RadiositySystem s;
  s.F = {n, std::vector<double>(n * n, 0.0)};
  for (int i = 0; i < n; ++i) {
    s.area.push_back(1.0);
    s.rho.push_back(Color(rho));
    s.emission.push_back(Color(i == 0 ? 1.0 : 0.0));
    for (int j = 0; j < n; ++j) s.F(i, j) = i == j ? 0 : row / (n - 1);
  }
  return s;
}

// Two patches facing each other and a third that nothing reflects into (its row is
// zero): R F = [[0, p], [q, 0], 0] has eigenvalues +-sqrt(p q) and 0.
gi::RadiositySystem facing_pair(double p, double q) {
  gi::RadiositySystem s;
  s.area = {1, 1, 1};
  s.rho = {Color(p, 0.5, 0.2), Color(q, 0.5, 0.2), Color(0.7)};
  s.emission = {Color(1), Color(0), Color(0)};
  s.F = {3, {0, 1, 0, 1, 0, 0, 0, 0, 0}};
  return s;
}

}  // namespace

TEST(Ex12_1_SpectralRadius, AClosedRoomOfUniformReflectance) {
  const gi::SpectralRadius r = gi::spectral_radius(closed_room(6, 0.6), 1);
  EXPECT_NEAR(r.value(), 0.6, 1e-7)
      << "in a closed room (rows of F sum to 1) of uniform rho, rho(R F) = rho: got " << r.value()
      << (std::abs(r.value() - 1.6) < 1e-3 ? " -- that is the eigenvalue of R F + I: subtract the shift, 1" : "");
  EXPECT_TRUE(r.converged) << "the growth factors agree at once in this room: the iteration must say it converged";
}

TEST(Ex12_1_SpectralRadius, LightThatEscapesShrinksIt) {
  // Rows of F summing to 0.8 (a fifth of the light leaves the room): rho(R F) = 0.9 * 0.8.
  const gi::SpectralRadius r = gi::spectral_radius(closed_room(5, 0.9, 0.8), 0);
  EXPECT_NEAR(r.value(), 0.72, 1e-7) << "rows of F that sum to 0.8 and rho = 0.9: rho(R F) = 0.72, not the "
                                        "reflectance; got "
                                     << r.value();
}

TEST(Ex12_1_SpectralRadius, TwoFacingPatchesNeedTheShift) {
  // Eigenvalues +-sqrt(0.4): without the shift by I the two are equally large, the
  // iterate swings between two vectors and the growth factors never settle.
  const gi::SpectralRadius r = gi::spectral_radius(facing_pair(0.5, 0.8), 0);
  EXPECT_TRUE(r.converged) << "R F = [[0, 0.5], [0.8, 0]] has eigenvalues +-0.632: iterate with R F + I, whose "
                              "largest eigenvalue 1.632 dominates, so that the growth factors converge";
  EXPECT_NEAR(r.value(), std::sqrt(0.4), 1e-6) << "rho(R F) = sqrt(0.5 * 0.8) = 0.6325, got " << r.value();
}

TEST(Ex12_1_SpectralRadius, TheBoundsBracketIt) {
  // Collatz-Wielandt: for a positive x the smallest growth factor is below rho(R F),
  // the largest above, at every step. After two steps they have not met yet.
  const double exact = std::sqrt(0.4);
  const gi::SpectralRadius r = gi::spectral_radius(facing_pair(0.5, 0.8), 0, 1e-15, 2);
  EXPECT_LE(r.lower, exact + 1e-12) << "lower is the smallest (R F x)_i / x_i, a lower bound: got " << r.lower
                                    << " above rho = " << exact;
  EXPECT_GE(r.upper, exact - 1e-12) << "upper is the largest (R F x)_i / x_i, an upper bound: got " << r.upper
                                    << " below rho = " << exact;
  EXPECT_LT(r.lower, r.upper) << "after 2 steps the bounds have not met: lower < upper";
}

TEST(Ex12_1_SpectralRadius, ARowOfZerosIsLeftOut) {
  // The third element gathers nothing: x dies out on it, and its growth factor (0) is
  // not a bound on anything.
  const gi::SpectralRadius r = gi::spectral_radius(facing_pair(0.5, 0.8), 0);
  EXPECT_GT(r.lower, 0.5) << "lower = " << r.lower << ": an element x has died out on (a row of zeros: nothing "
                             "reflects into it) must be left out of the growth factors";
}

TEST(Ex12_1_SpectralRadius, OneChannelAtATime) {
  const gi::RadiositySystem s = facing_pair(0.5, 0.8);  // green: 0.5 both; blue: 0.2 both
  EXPECT_NEAR(gi::spectral_radius(s, 1).value(), 0.5, 1e-6) << "channel 1 (green): rho_g = 0.5 on both, so 0.5";
  EXPECT_NEAR(gi::spectral_radius(s, 2).value(), 0.2, 1e-6) << "channel 2 (blue): 0.2; use the channel asked for";
}

TEST(Ex12_1_SpectralRadius, StopsAtTheIterationLimit) {
  const gi::SpectralRadius r = gi::spectral_radius(facing_pair(0.5, 0.8), 0, 0.0, 7);
  EXPECT_EQ(r.iterations, 7) << "with tolerance 0 the bounds never agree: stop after max_iterations (7)";
  EXPECT_FALSE(r.converged) << "and say it did not converge";
}

TEST(Ex12_1_SpectralRadius, ManyIterationsStayFinite) {
  // (R F + I)^k x grows like 1.9^k: 2000 steps overflow a double unless x is scaled
  // back after each one. (A negative tolerance no pair of bounds can meet: all 2000 run.)
  const gi::SpectralRadius r = gi::spectral_radius(closed_room(4, 0.9), 0, -1.0, 2000);
  EXPECT_TRUE(std::isfinite(r.lower) && std::isfinite(r.upper))
      << "after 2000 steps the bounds are " << r.lower << " and " << r.upper
      << ": scale x after every step (divide by its largest entry), or it overflows";
  EXPECT_NEAR(r.value(), 0.9, 1e-9) << "the closed room of rho = 0.9";
}

TEST(Ex12_1_SpectralRadius, NothingReflectedNothingToIterate) {
  const gi::SpectralRadius r = gi::spectral_radius(closed_room(3, 0.0), 0);
  EXPECT_NEAR(r.value(), 0.0, 1e-12) << "rho = 0: R F = 0, whose spectral radius is 0";
}
