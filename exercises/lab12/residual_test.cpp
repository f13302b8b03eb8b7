// Graded tests of exercise 12.2: the relative residual of a float solution, summed in
// double. One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/radiosity/system/float_sweep.hpp"
#include "support/print.hpp"

namespace {

// Two elements, F = [[0, 0.5], [0.25, 0]] (not symmetric: a transposed F shows),
// rho = (0.5, 0.4, 0.3) and (0.8, 0.6, 0.2), E = (1, 0, 0.5) and (0, 0.5, 0).
gi::FloatSystem two() {
  return {2, {0.0f, 0.5f, 0.25f, 0.0f}, {0.5f, 0.4f, 0.3f, 0.8f, 0.6f, 0.2f}, {1.0f, 0.0f, 0.5f, 0.0f, 0.5f, 0.0f}};
}

// The slips the tests tell apart: what a residual that makes one of them comes out as.
struct Slips {
  bool transposed = false, red_rho = false, no_emission = false, relative_to_B = false, squared = false;
};

// ||E + R F B - B||_2 / ||E||_2 of `two()`, worked out here in double (with a slip, if asked).
double by_hand(const std::vector<float>& B, Slips slip = {}) {
  const gi::FloatSystem s = two();
  double r2 = 0, e2 = 0;
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      const auto f = [&](int row, int col) { return double(slip.transposed ? s.F[2 * col + row] : s.F[2 * row + col]); };
      const double gathered = f(i, 0) * B[c] + f(i, 1) * B[3 + c];
      const double rho = s.rho[3 * i + (slip.red_rho ? 0 : c)];
      const double r = (slip.no_emission ? 0.0 : s.emission[3 * i + c]) + rho * gathered - B[3 * i + c];
      const double norm = slip.relative_to_B ? B[3 * i + c] : s.emission[3 * i + c];
      r2 += r * r, e2 += norm * norm;
    }
  return slip.squared ? r2 / e2 : std::sqrt(r2 / e2);
}

// Your relative residual of `two()` at B against the formula, the matching slip named first.
void expect_residual(const std::vector<float>& B, const char* message) {
  const double got = gi::relative_residual(two(), B), want = by_hand(B);
  const struct {
    Slips slip;
    const char* what;
  } slips[] = {{{.transposed = true}, "F is transposed: element i gathers through its row, F[i * n + j]. "},
               {{.red_rho = true}, "one reflectance for every channel: rho of channel c is rho[3 i + c]. "},
               {{.no_emission = true}, "E is left out: the residual is E + R F B - B. "},
               {{.relative_to_B = true}, "divided by ||B||: the residual is relative to the emission, ||E||. "},
               {{.squared = true}, "the square of the ratio: take the square root. "}};
  std::string why;
  for (const auto& [slip, what] : slips)
    if (std::abs(got - by_hand(B, slip)) < 1e-12 && std::abs(got - want) > 1e-12) why = what;
  EXPECT_NEAR(got, want, 1e-12) << why << message << " Want " << want << ", got " << got << ".";
}

}  // namespace

TEST(Ex12_2_Residual, TheFormula) {
  expect_residual({1.5f, 0.5f, 0.75f, 0.25f, 1.0f, 0.125f},
                  "||E + R F B - B||_2 / ||E||_2 over every element and channel.");
}

TEST(Ex12_2_Residual, ZeroAtTheSolution) {
  // E chosen so that B is the solution: E = B - R F B, worked out in double and rounded
  // to float. What is left of the residual is that rounding, below 1e-7 of E.
  gi::FloatSystem s = two();
  const std::vector<float> B = {2.0f, 1.0f, 0.5f, 0.5f, 1.0f, 0.25f};
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      const double gathered = double(s.F[2 * i]) * B[c] + double(s.F[2 * i + 1]) * B[3 + c];
      s.emission[3 * i + c] = float(B[3 * i + c] - s.rho[3 * i + c] * gathered);
    }
  EXPECT_NEAR(gi::relative_residual(s, B), 0.0, 1e-7)
      << "B is the solution (to float round-off of E): the residual E + R F B - B is about 0";
}

TEST(Ex12_2_Residual, FGathersAlongItsRow) {
  // B of element 1 only: element 0 gathers it through F_01 = 0.5, element 1 nothing.
  expect_residual({0.0f, 0.0f, 0.0f, 2.0f, 2.0f, 2.0f},
                  "element i gathers sum_j F_ij B_j, F row-major: F[i * n + j].");
}

TEST(Ex12_2_Residual, ReflectanceAndEmissionPerChannel) {
  expect_residual({0.5f, 2.0f, 1.0f, 1.0f, 0.25f, 3.0f},
                  "each channel c of element i has its own rho_i,c and E_i,c (index 3 i + c).");
}

TEST(Ex12_2_Residual, RelativeToTheEmission) {
  // The same residual, E twice as large and B too: the relative residual is the same.
  gi::FloatSystem s = two();
  const std::vector<float> B = {1.5f, 0.5f, 0.75f, 0.25f, 1.0f, 0.125f};
  std::vector<float> B2 = B;
  for (float& e : s.emission) e *= 2;
  for (float& b : B2) b *= 2;
  EXPECT_NEAR(gi::relative_residual(s, B2), gi::relative_residual(two(), B), 1e-12)
      << "divide by ||E||_2: twice the light, twice the residual, the same relative residual";
}

TEST(Ex12_2_Residual, NoEmissionMeansTheResidualItself) {
  gi::FloatSystem s = two();
  for (float& e : s.emission) e = 0;
  const std::vector<float> B = {0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f};
  // r = R F B - B: only element 0's blue channel, -1; element 1 gathers 0.2 * 0.25 * 1.
  const double want = std::sqrt(1.0 + std::pow(0.2f * 0.25f, 2));
  const double got = gi::relative_residual(s, B);
  EXPECT_NEAR(got, want, 1e-7) << "with E = 0 there is nothing to divide by: return ||r||_2 itself (" << want
                               << "), never NaN; got " << got;
}

TEST(Ex12_2_Residual, SumsInDouble) {
  // 2000 elements that see each other equally, B the solution to float precision:
  // the true residual is the rounding of E, about 3e-8 relative. Float sums of 2000
  // terms lose ~1e-6 of their size: a residual summed in float shows its own noise.
  const int n = 2000;
  gi::Rng rng(12);
  gi::FloatSystem s{n, std::vector<float>(std::size_t(n) * n, 0.5f / (n - 1)), {}, {}};
  std::vector<float> B(3 * n);
  for (int i = 0; i < n; ++i) {
    s.F[std::size_t(i) * n + i] = 0;
    for (int c = 0; c < 3; ++c) B[3 * i + c] = float(0.5 + rng.uniform()), s.rho.push_back(0.9f);
  }
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      double gathered = 0;
      for (int j = 0; j < n; ++j) gathered += double(s.F[std::size_t(i) * n + j]) * B[3 * j + c];
      s.emission.push_back(float(B[3 * i + c] - double(s.rho[3 * i + c]) * gathered));
    }
  const double got = gi::relative_residual(s, B);
  EXPECT_LT(got, 1e-7) << "the relative residual is " << got << ", but B solves the system to float precision "
                       << "(the true value is about 3e-8): sum the products F_ij B_j, and the squares, in double -- "
                          "a float sum of 2000 terms is only good to about 1e-6 of its size";
}
