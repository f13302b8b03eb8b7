// Graded tests of exercise 10.1: a Southwell step with the incremental residual
// update. One point per test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "gi/radiosity/system/solvers.hpp"
#include "support/print.hpp"

using gi::Color;

namespace {
gi::RadiositySystem three() {
  gi::RadiositySystem s;
  s.area = {1.0, 2.0, 0.5};
  s.rho = {Color(0.5, 0.4, 0.3), Color(0.8), Color(0.2, 0.6, 0.9)};
  s.emission = {Color(1.0), Color(0.0), Color(0.0, 0.5, 0.0)};
  s.F = {3, {0.0, 0.5, 0.2, 0.25, 0.0, 0.1, 0.4, 0.4, 0.0}};
  return s;
}

// Four elements, for the first pick test: every wrong rule picks another one.
gi::RadiositySystem four() {
  gi::RadiositySystem s;
  s.area = {1.0, 2.0, 0.5, 1.0};
  s.rho = {Color(0.5), Color(0.5), Color(0.5), Color(0.5)};
  s.emission = {Color(1.0), Color(0.0), Color(0.0), Color(0.0)};
  s.F = {4, {0.0, 0.2, 0.1, 0.1, 0.1, 0.0, 0.1, 0.1, 0.1, 0.3, 0.0, 0.1, 0.2, 0.2, 0.1, 0.0}};
  return s;
}

// The rule a wrong pick matches, among the slips students make, or "".
std::string rule_of(const gi::RadiositySystem& s, const std::vector<Color>& r, int picked, int want) {
  if (picked == want || picked < 0 || picked >= s.size()) return "";
  const auto argmax = [&](auto size) {
    int best = 0;
    for (int j = 1; j < s.size(); ++j)
      if (size(j) > size(best)) best = j;
    return best;
  };
  const auto largest = [&](int j) { return std::max({std::abs(r[j].x), std::abs(r[j].y), std::abs(r[j].z)}); };
  const struct {
    int pick;
    const char* rule;
  } rules[] = {
      {argmax([&](int j) { return largest(j) * s.area[j]; }),
       "the largest |r_i| A_i: weighting by area is progressive refinement's rule (unshot power), not Southwell's"},
      {argmax([&](int j) { return std::abs(r[j].x + r[j].y + r[j].z) * s.area[j]; }),
       "the largest area-weighted sum of channels: that is unshot power, progressive refinement's rule"},
      {argmax([&](int j) { return (r[j].x + r[j].y + r[j].z) * s.area[j]; }),
       "the most unshot power, sum of the channels times the area: progressive refinement's rule, not "
       "Southwell's"},
      {argmax([&](int j) { return std::max({r[j].x, r[j].y, r[j].z}); }),
       "the largest signed residual: a negative residual counts by its size |r_i|"},
      {argmax([&](int j) { return std::abs(r[j].x) + std::abs(r[j].y) + std::abs(r[j].z); }),
       "the largest sum of the channels: the size of a residual is its largest channel"},
      {argmax([&](int j) { return std::abs(r[j].x); }), "the largest red residual: look at every channel"},
      {argmax([&](int j) { return -largest(j); }), "the smallest residual: Southwell relaxes the largest"},
      {argmax([&](int j) { return j == 0 ? -1.0 : largest(j); }),
       "the largest residual after element 0, which is never compared: start from i = 0 and compare every element"},
  };
  for (const auto& [pick, rule] : rules)
    if (pick == picked && pick != want)
      return "element " + std::to_string(picked) + " has " + rule + "; relax element " + std::to_string(want) +
             ", the largest max_c |r_i,c|. ";
  return "";
}

// Element j's residual after relaxing element 0 (r_0 = 2): the slip a wrong value
// matches, or "". r_j += rho_j F_j0 r_0 is the update; rho_i is element 0's reflectance.
std::string spread_slip(double got, const char* name, double r_j, double rho_j, double rho_i, double F_ji, double F_ij,
                        int j, const char* F_ji_name, const char* F_ij_name) {
  const double relaxed = 2.0;
  const auto near = [&](double v) { return std::abs(got - v) < 1e-12; };
  const std::string J = std::to_string(j);
  const std::string values = std::string(name) + " = " + testing::PrintToString(got) + ", want " +
                             testing::PrintToString(r_j) + " + rho_" + J + " " + F_ji_name + " r_0 = " +
                             testing::PrintToString(r_j) + " + " + testing::PrintToString(rho_j) + " * " +
                             testing::PrintToString(F_ji) + " * 2 = " +
                             testing::PrintToString(r_j + rho_j * F_ji * relaxed) + ": ";
  if (near(r_j + rho_j * F_ij * relaxed))
    return values + "you spread through " + F_ij_name + " (row i of F); element j gathers from i through " +
           F_ji_name + " (column i). ";
  if (near(r_j + F_ji * relaxed))
    return values + "you left out rho_" + J + ": what element " + J + " gathers is reflected by its reflectance. ";
  if (near(r_j + rho_i * F_ji * relaxed))
    return values + "you used rho_0, the relaxed element's reflectance; the light is reflected by the receiver, "
                    "rho_" + J + ". ";
  if (near(r_j))
    return values + "r_" + J + " did not change: spread the residual r_0 you relax (keep a copy of it) before you "
                    "set r_0 = 0, or you spread 0. ";
  if (near(r_j - rho_j * F_ji * relaxed))
    return values + "you subtracted: relaxing element 0 raises B_0 by r_0, so element " + J +
           " gathers more, and its residual grows: r_j += rho_j F_j0 r_0. ";
  return values;
}

// southwell_step's pick, and what is wrong with it (the matching slip first).
void expect_pick(const gi::RadiositySystem& s, std::vector<Color> r, int want, const char* message) {
  std::vector<Color> B(s.size(), Color(0.0)), r_before = r;
  const int picked = gi::southwell_step(s, B, r);
  EXPECT_EQ(picked, want) << rule_of(s, r_before, picked, want) << message;
}
}  // namespace

TEST(Ex10_1_Southwell, PicksByTheResidualNotTheArea) {
  // Element 1 has the most unshot power |r_1| A_1 = 0.6, element 0 the largest residual 0.5.
  expect_pick(four(), {Color(0.5), Color(0.3), Color(0.45), Color(0.05)}, 0,
              "Southwell relaxes the largest residual |r_i|, element 0 (0.5); weighting by area (|r_i| A_i, "
              "element 1's 0.6) is progressive refinement's rule, not this one");
}

TEST(Ex10_1_Southwell, PicksTheLargestResidual) {
  expect_pick(three(), {Color(0.3), Color(-0.5), Color(0.4)}, 1,
              "the largest |r_i|: a negative residual counts by its size");
}

TEST(Ex10_1_Southwell, LooksAtEveryChannel) {
  expect_pick(three(), {Color(0.2), Color(0.1, 0.1, 0.9), Color(0.3)}, 1,
              "element 1's blue residual 0.9 is the largest");
}

TEST(Ex10_1_Southwell, PicksByTheLargestChannelNotTheSum) {
  expect_pick(three(), {Color(0.5, 0.0, 0.0), Color(0.0), Color(0.3, 0.3, 0.3)}, 0,
              "the size of a residual is its largest channel, max_c |r_i,c|: element 0 (0.5), although element "
              "2's channels add up to more (0.9)");
}

TEST(Ex10_1_Southwell, RelaxesTheChosenElement) {
  const gi::RadiositySystem s = three();
  std::vector<Color> B = {Color(0.5), Color(0.0), Color(0.0)}, r = {Color(2.0), Color(0.1), Color(0.3)};
  gi::southwell_step(s, B, r);
  EXPECT_NEAR(B[0].x, 2.5, 1e-12) << "B_i += r_i";
  EXPECT_EQ(r[0], Color(0.0)) << "after relaxing, r_i = 0 (F_ii = 0)";
}

TEST(Ex10_1_Southwell, UpdatesTheOthersThroughColumnI) {
  const gi::RadiositySystem s = three();
  std::vector<Color> B(3, Color(0.0)), r = {Color(2.0), Color(0.1), Color(0.3)};
  gi::southwell_step(s, B, r);
  // r_j += rho_j F_j0 * 2: F_10 = 0.25, F_20 = 0.4 (not F_01 = 0.5, F_02 = 0.2).
  EXPECT_NEAR(r[1].x, 0.1 + 0.8 * 0.25 * 2.0, 1e-12)
      << spread_slip(r[1].x, "r_1 (red)", 0.1, 0.8, 0.5, 0.25, 0.5, 1, "F_10", "F_01")
      << "element j gathers from i through F_ji (column i of F), reflected by its own rho_j";
  EXPECT_NEAR(r[2].z, 0.3 + 0.9 * 0.4 * 2.0, 1e-12)
      << spread_slip(r[2].z, "r_2 (blue)", 0.3, 0.9, 0.3, 0.4, 0.2, 2, "F_20", "F_02")
      << "element j gathers from i through F_ji (column i of F), reflected by its own rho_j";
}

TEST(Ex10_1_Southwell, ResidualStaysTheTrueResidual) {
  const gi::RadiositySystem s = three();
  std::vector<Color> B(3, Color(0.0)), r = s.emission;
  for (int step = 0; step < 25; ++step) gi::southwell_step(s, B, r);
  const std::vector<Color> truth = gi::residual(s, B);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(r[i][c], truth[i][c], 1e-12) << "the incremental update must keep r = E - (I - RF) B";
}

TEST(Ex10_1_Southwell, SolverConvergesToTheDirectSolution) {
  const gi::RadiositySystem s = three();
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  options.max_steps = 10000;
  const gi::SolverResult r = gi::solve_southwell(s, options), direct = gi::solve_direct(s);
  ASSERT_EQ(r.status, gi::SolveStatus::Converged)
      << "solve_southwell, built on your step, must converge on a system with rho < 1";
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(r.B[i][c], direct.B[i][c], 1e-10)
          << "element " << i << ", channel " << c << ": Southwell's fixed point is the solution of (I - RF) B = E";
}
