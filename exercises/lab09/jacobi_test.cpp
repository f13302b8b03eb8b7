// Graded tests of exercise 9.1: one Jacobi iteration. One point per test. A wrong
// answer is compared with the usual slips (system.hpp) and told which one it is.
#include <gtest/gtest.h>

#include "support/print.hpp"
#include "system.hpp"

using gi::Color;

namespace {
// Your iteration from `old` against the formula, every element and channel.
void expect_iteration(const gi::RadiositySystem& s, const std::vector<Color>& old, std::vector<Color> next) {
  const std::vector<Color> want = lab09::jacobi_by_hand(s, old);
  gi::jacobi_iteration(s, old, next);
  ASSERT_EQ(next.size(), want.size()) << "B_new keeps one radiosity per element";
  EXPECT_TRUE(lab09::same(next, want)) << lab09::jacobi_slip(s, old, next) << " (got " << testing::PrintToString(next)
                                       << ", want " << testing::PrintToString(want) << ")";
}
}  // namespace

TEST(Ex9_1_Jacobi, OneIterationFromEmission) {
  const gi::RadiositySystem s = lab09::three();
  expect_iteration(s, s.emission, std::vector<Color>(3));
}

TEST(Ex9_1_Jacobi, GathersFromOldValuesOnly) {
  const gi::RadiositySystem s = lab09::three();
  const std::vector<Color> old = {Color(2.0), Color(1.0), Color(3.0)};
  expect_iteration(s, old, old);  // B_new starts as a copy of B_old: a Jacobi step must not read what it writes
}

TEST(Ex9_1_Jacobi, ReflectanceMultipliesTheGatheredLight) {
  gi::RadiositySystem s = lab09::three();
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, {Color(1.0), Color(1.0), Color(1.0)}, next);
  EXPECT_NEAR(next[1].x, 0.8 * (0.25 + 0.1), 1e-12)
      << "element 1 emits nothing and gathers F_10 + F_12 = 0.35 of B = 1, reflected by rho_1 = 0.8: "
      << lab09::jacobi_slip(s, {Color(1.0), Color(1.0), Color(1.0)}, next);
}

TEST(Ex9_1_Jacobi, RowsNotColumns) {
  const gi::RadiositySystem s = lab09::three();
  const std::vector<Color> old = {Color(0.0), Color(1.0), Color(0.0)};
  std::vector<Color> next(3);
  gi::jacobi_iteration(s, old, next);
  EXPECT_NEAR(next[0].y, 1.0 + 0.4 * 0.5, 1e-12)
      << "only element 1 is lit: element 0 gets E_0 + rho_0 F_01 B_1 = 1 + 0.4 * 0.5. "
      << lab09::jacobi_slip(s, old, next);
}

TEST(Ex9_1_Jacobi, EveryChannelOnItsOwn) {
  const gi::RadiositySystem s = lab09::three();
  expect_iteration(s, {Color(1.0, 2.0, 3.0), Color(3.0, 1.0, 2.0), Color(2.0, 3.0, 1.0)}, std::vector<Color>(3));
}

TEST(Ex9_1_Jacobi, SolverConvergesToTheDirectSolution) {
  const gi::RadiositySystem s = lab09::three();
  const gi::SolverResult direct = gi::solve_direct(s);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  const gi::SolverResult jacobi = gi::solve_jacobi(s, options);
  ASSERT_EQ(jacobi.status, gi::SolveStatus::Converged)
      << "solve_jacobi, built on your iteration, must converge on a system with rho < 1";
  EXPECT_TRUE(lab09::same(jacobi.B, direct.B, 1e-10))
      << "Jacobi's fixed point is the solution of (I - RF) B = E (got " << testing::PrintToString(jacobi.B)
      << ", the direct solution is " << testing::PrintToString(direct.B) << ")";
}

TEST(Ex9_1_Jacobi, DivergenceIsReported) {
  gi::SolverOptions options;
  options.max_steps = 10000;
  const gi::SolverResult r = gi::solve_jacobi(lab09::runaway(), options);
  EXPECT_EQ(r.status, gi::SolveStatus::Diverged) << "rho = 1.4: the iteration grows without bound";
  for (const Color& b : r.B) EXPECT_TRUE(gi::is_finite(b)) << "the solver stops before B overflows";
}
