// Hidden graded tests of lab 9 (the autograder's): random systems of seven elements,
// every channel with its own reflectance. One point per test.
#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "support/print.hpp"
#include "../system.hpp"

using gi::Color;

namespace {
// Seven elements, rows of F summing to at most 0.9, reflectances and emission per channel.
gi::RadiositySystem random_system(std::uint64_t seed) {
  gi::Rng rng(seed);
  const int n = 7;
  gi::RadiositySystem s;
  s.F = {n, std::vector<double>(n * n, 0.0)};
  for (int i = 0; i < n; ++i) {
    s.area.push_back(0.5 + rng.uniform());
    s.rho.push_back(Color(rng.uniform(), rng.uniform(), rng.uniform()));
    s.emission.push_back(rng.uniform() < 0.3 ? Color(rng.uniform(), rng.uniform(), rng.uniform()) : Color(0.0));
    for (int j = 0; j < n; ++j)
      if (j != i) s.F(i, j) = 0.9 / (n - 1) * rng.uniform();
  }
  return s;
}
std::vector<Color> random_b(gi::Rng& rng, int n) {
  std::vector<Color> b;
  for (int i = 0; i < n; ++i) b.push_back(Color(rng.uniform(), rng.uniform(), rng.uniform()));
  return b;
}
}  // namespace

TEST(Ex9_1_RandomSystems, OneIterationAsTheFormulaSays) {
  gi::Rng rng(909);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const gi::RadiositySystem s = random_system(seed);
    const std::vector<Color> old = random_b(rng, s.size());
    std::vector<Color> next = old;
    gi::jacobi_iteration(s, old, next);
    ASSERT_TRUE(lab09::same(next, lab09::jacobi_by_hand(s, old))) << "system " << seed << ": " << lab09::jacobi_slip(s, old, next);
  }
}

TEST(Ex9_2_RandomSystems, OneSweepAsTheFormulaSays) {
  gi::Rng rng(910);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const gi::RadiositySystem s = random_system(seed);
    const std::vector<Color> b = random_b(rng, s.size());
    const double omega = 0.5 + 1.4 * rng.uniform();
    std::vector<Color> got = b;
    gi::gauss_seidel_sweep(s, got, omega);
    ASSERT_TRUE(lab09::same(got, lab09::sweep_by_hand(s, b, omega)))
        << "system " << seed << ", omega = " << omega << ": " << lab09::sweep_slip(s, b, omega, got);
  }
}
