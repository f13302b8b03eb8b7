// Graded tests of exercise 9.1: one Jacobi iteration. One point per test.
#include <gtest/gtest.h>

#include "system.hpp"

using gi::Color;

namespace {
// B_new_i = E_i + rho_i sum_j F_ij B_old_j, written out.
std::vector<Color> by_hand(const gi::RadiositySystem& s, const std::vector<Color>& old) {
  std::vector<Color> b(3);
  for (int i = 0; i < 3; ++i) {
    Color g(0.0);
    for (int j = 0; j < 3; ++j) g += s.F(i, j) * old[j];
    b[i] = s.emission[i] + s.rho[i] * g;
  }
  return b;
}
void expect_equal(const std::vector<Color>& got, const std::vector<Color>& want, const char* why) {
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[i][c], want[i][c], 1e-12) << "element " << i << ": " << why;
}
}  // namespace

TEST(Ex9_1_Jacobi, OneIterationFromEmission) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, s.emission, next);
  expect_equal(next, by_hand(s, s.emission), "B_new_i = E_i + rho_i sum_j F_ij B_old_j");
}

TEST(Ex9_1_Jacobi, GathersFromOldValuesOnly) {
  const gi::RadiositySystem s = lab09::three();
  const std::vector<Color> old = {Color(2.0), Color(1.0), Color(3.0)};
  std::vector<Color> next = old;  // a Jacobi step must not read what it has just written
  gi::jacobi_iteration(s, old, next);
  expect_equal(next, by_hand(s, old), "read B_old only; using values updated in this iteration is Gauss-Seidel");
}

TEST(Ex9_1_Jacobi, ReflectanceMultipliesTheGatheredLight) {
  gi::RadiositySystem s = lab09::three();
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, {Color(1.0), Color(1.0), Color(1.0)}, next);
  EXPECT_NEAR(next[1].x, 0.8 * (0.25 + 0.1), 1e-12) << "element 1 gathers F_10 + F_12 = 0.35, times rho_1 = 0.8";
}

TEST(Ex9_1_Jacobi, RowsNotColumns) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, {Color(0.0), Color(1.0), Color(0.0)}, next);
  EXPECT_NEAR(next[0].y, 1.0 + 0.4 * 0.5, 1e-12) << "element 0 gathers F_01 B_1 (row 0 of F), not F_10 B_1";
}

TEST(Ex9_1_Jacobi, EveryChannelOnItsOwn) {
  const gi::RadiositySystem s = lab09::three();
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, {Color(1.0, 2.0, 3.0), Color(1.0, 2.0, 3.0), Color(1.0, 2.0, 3.0)}, next);
  EXPECT_NEAR(next[2].z, 0.9 * 0.8 * 3.0, 1e-12);
  EXPECT_NEAR(next[2].y, 0.5 + 0.6 * 0.8 * 2.0, 1e-12) << "reflectance, emission and B are per colour channel";
}

TEST(Ex9_1_Jacobi, SolverConvergesToTheDirectSolution) {
  const gi::RadiositySystem s = lab09::three();
  const gi::SolverResult direct = gi::solve_direct(s);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  const gi::SolverResult jacobi = gi::solve_jacobi(s, options);
  ASSERT_EQ(jacobi.status, gi::SolveStatus::Converged);
  expect_equal(jacobi.B, direct.B, "Jacobi's fixed point is the solution of (I - RF) B = E");
}

TEST(Ex9_1_Jacobi, DivergenceIsReported) {
  gi::SolverOptions options;
  options.max_steps = 10000;
  const gi::SolverResult r = gi::solve_jacobi(lab09::runaway(), options);
  EXPECT_EQ(r.status, gi::SolveStatus::Diverged) << "rho = 1.4: the iteration grows without bound";
  for (const Color& b : r.B) EXPECT_TRUE(gi::is_finite(b));
}
