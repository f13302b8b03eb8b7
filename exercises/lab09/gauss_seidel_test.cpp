// Graded tests of exercise 9.2: one Gauss-Seidel sweep. One point per test. A wrong
// answer is compared with the usual slips (system.hpp) and told which one it is;
// nothing here calls your Jacobi iteration (exercise 9.1).
#include <gtest/gtest.h>

#include "support/print.hpp"
#include "system.hpp"

using gi::Color;

namespace {
// Your sweep from `b` against the formula, every element and channel.
void expect_sweep(const gi::RadiositySystem& s, const std::vector<Color>& b, double omega) {
  const std::vector<Color> want = lab09::sweep_by_hand(s, b, omega);
  std::vector<Color> got = b;
  gi::gauss_seidel_sweep(s, got, omega);
  ASSERT_EQ(got.size(), want.size()) << "the sweep keeps one radiosity per element";
  EXPECT_TRUE(lab09::same(got, want)) << lab09::sweep_slip(s, b, omega, got) << " (got "
                                      << testing::PrintToString(got) << ", want " << testing::PrintToString(want)
                                      << ")";
}
}  // namespace

TEST(Ex9_2_GaussSeidel, UsesTheNewestValues) {
  expect_sweep(lab09::three(), {Color(2.0), Color(1.0), Color(3.0)}, 1.0);
}

TEST(Ex9_2_GaussSeidel, WorksInPlace) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> b = s.emission;
  gi::gauss_seidel_sweep(s, b);
  EXPECT_NE(b[1], Color(0.0)) << "update B itself: the sweep has no separate output (element 1 emits nothing, "
                                 "but gathers from element 0)";
}

TEST(Ex9_2_GaussSeidel, EmissionAndReflectanceCount) {
  // From B = 0: B_0 = E_0 = 1; B_1 = rho_1 F_10 B_0 = 0.8 * 0.25; B_2 = E_2 + rho_2 (F_20 B_0 + F_21 B_1).
  expect_sweep(lab09::three(), std::vector<Color>(3, Color(0.0)), 1.0);
}

TEST(Ex9_2_GaussSeidel, EveryChannelOnItsOwn) {
  expect_sweep(lab09::three(), {Color(1.0, 2.0, 3.0), Color(3.0, 1.0, 2.0), Color(2.0, 3.0, 1.0)}, 1.0);
}

TEST(Ex9_2_GaussSeidel, OverRelaxation) {
  expect_sweep(lab09::three(), {Color(2.0), Color(1.0), Color(3.0)}, 1.5);
}

TEST(Ex9_2_GaussSeidel, SolverConvergesToTheDirectSolution) {
  const gi::RadiositySystem s = lab09::three();
  const gi::SolverResult direct = gi::solve_direct(s);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  for (double omega : {1.0, 1.3}) {
    const gi::SolverResult r = gi::solve_gauss_seidel(s, options, omega);
    ASSERT_EQ(r.status, gi::SolveStatus::Converged)
        << "solve_gauss_seidel, built on your sweep, must converge on a system with rho < 1 (omega = " << omega << ")";
    EXPECT_TRUE(lab09::same(r.B, direct.B, 1e-10))
        << "omega = " << omega << ": the sweep's fixed point is the solution of (I - RF) B = E (got "
        << testing::PrintToString(r.B) << ", the direct solution is " << testing::PrintToString(direct.B) << ")";
  }
}

TEST(Ex9_2_GaussSeidel, FewerSweepsThanJacobi) {
  const gi::RadiositySystem s = lab09::three();
  gi::SolverOptions options;
  options.tolerance = 1e-10;
  const int jacobi = lab09::jacobi_iterations_by_hand(s, options.tolerance);
  const std::size_t sweeps = gi::solve_gauss_seidel(s, options).history.size();
  EXPECT_LT(sweeps, static_cast<std::size_t>(jacobi))
      << "your sweeps needed " << sweeps << " passes, Jacobi needs " << jacobi << ": using the newest values "
      << "should converge faster";
}
