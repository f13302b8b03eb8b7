#include "gi/radiosity/system/float_sweep.hpp"

#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/radiosity/system/solvers.hpp"

TEST(FloatSweep, BlockedSweepIsGaussSeidel) {
  // 11 elements (two blocks of four and a tail of three): every sweep must equal the
  // plain double Gauss-Seidel sweep to float round-off.
  const int n = 11;
  gi::Rng rng(3);
  gi::RadiositySystem d;
  d.F = {n, std::vector<double>(n * n)};
  for (int i = 0; i < n; ++i) {
    d.area.push_back(1);
    d.rho.push_back(gi::Color(0.3 + 0.6 * rng.uniform(), 0.5, 0.9 * rng.uniform()));
    d.emission.push_back(gi::Color(rng.uniform() < 0.3 ? 1.0 : 0.0, 0.2, 0.0));
    for (int j = 0; j < n; ++j) d.F(i, j) = i == j ? 0 : 0.18 * rng.uniform();
  }
  gi::FloatSystem f{n, std::vector<float>(d.F.values.begin(), d.F.values.end()), {}, {}};
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) f.rho.push_back(float(d.rho[i][c])), f.emission.push_back(float(d.emission[i][c]));
  std::vector<gi::Color> Bd = d.emission;
  std::vector<float> Bf(f.emission.begin(), f.emission.end());
  for (int sweep = 0; sweep < 4; ++sweep) {
    gi::gauss_seidel_sweep(d, Bd);
    gi::gauss_seidel_sweep_float(f, Bf);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(Bf[3 * i + c], Bd[i][c], 1e-5) << "sweep " << sweep << ", element " << i;
  }
  EXPECT_NEAR(gi::relative_residual(f, Bf), 0.0, 0.05);
  EXPECT_FLOAT_EQ(gi::sum_all({1.0f, 2.0f, 3.5f}), 6.5f);
}
