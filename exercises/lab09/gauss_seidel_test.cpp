// Graded tests of exercise 9.2: one Gauss-Seidel sweep. One point per test.
#include <gtest/gtest.h>

#include "system.hpp"

using gi::Color;

namespace {
// In order, each element from the newest values: the sweep written out.
std::vector<Color> by_hand(const gi::RadiositySystem& s, std::vector<Color> b, double omega) {
  for (int i = 0; i < 3; ++i) {
    Color g(0.0);
    for (int j = 0; j < 3; ++j) g += s.F(i, j) * b[j];
    b[i] = (1 - omega) * b[i] + omega * (s.emission[i] + s.rho[i] * g);
  }
  return b;
}
}  // namespace

TEST(Ex9_2_GaussSeidel, UsesTheNewestValues) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> b = {Color(2.0), Color(1.0), Color(3.0)};
  const std::vector<Color> want = by_hand(s, b, 1.0);
  gi::gauss_seidel_sweep(s, b);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(b[i].x, want[i].x, 1e-12) << "element " << i
                                          << ": gather from B as it is now, with elements before i already updated";
}

TEST(Ex9_2_GaussSeidel, WorksInPlace) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> b = s.emission;
  gi::gauss_seidel_sweep(s, b);
  EXPECT_NE(b[1], Color(0.0)) << "update B itself: the sweep has no separate output";
}

TEST(Ex9_2_GaussSeidel, EmissionAndReflectanceCount) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> b(3, Color(0.0));
  gi::gauss_seidel_sweep(s, b);
  // B_0 = E_0 = 1; B_1 = rho_1 F_10 B_0 = 0.8 * 0.25; B_2 = E_2 + rho_2 (F_20 B_0 + F_21 B_1).
  EXPECT_NEAR(b[0].x, 1.0, 1e-12);
  EXPECT_NEAR(b[1].x, 0.2, 1e-12);
  EXPECT_NEAR(b[2].y, 0.5 + 0.6 * (0.4 * 1.0 + 0.4 * 0.2), 1e-12);
}

TEST(Ex9_2_GaussSeidel, OverRelaxation) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> b = {Color(2.0), Color(1.0), Color(3.0)};
  const std::vector<Color> want = by_hand(s, b, 1.5);
  gi::gauss_seidel_sweep(s, b, 1.5);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(b[i].z, want[i].z, 1e-12) << "SOR: B_i = (1 - omega) B_i + omega * (the Gauss-Seidel value)";
}

TEST(Ex9_2_GaussSeidel, SolverConvergesToTheDirectSolution) {
  const gi::RadiositySystem s = lab09::three();
  const gi::SolverResult direct = gi::solve_direct(s);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  for (double omega : {1.0, 1.3}) {
    const gi::SolverResult r = gi::solve_gauss_seidel(s, options, omega);
    ASSERT_EQ(r.status, gi::SolveStatus::Converged);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.B[i].y, direct.B[i].y, 1e-10);
  }
}

TEST(Ex9_2_GaussSeidel, FewerSweepsThanJacobi) {
  const gi::RadiositySystem s = lab09::three();
  gi::SolverOptions options;
  options.tolerance = 1e-10;
  EXPECT_LT(gi::solve_gauss_seidel(s, options).history.size(), gi::solve_jacobi(s, options).history.size())
      << "using the newest values should converge faster than Jacobi";
}
