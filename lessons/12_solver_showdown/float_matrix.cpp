// Lesson 12, steps 3 and 5: Gauss-Seidel on a float matrix (float_matrix.hpp).
#include "float_matrix.hpp"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/system/float_sweep.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/report/table.hpp"

namespace lesson12 {

// 3. Float against double: where each one's residual stops falling.
void precision(const gi::RadiositySystem& s, gi::Lesson& lesson) {
  gi::FloatSystem f{s.size(), std::vector<float>(s.F.values.begin(), s.F.values.end()), {}, {}};
  for (int i = 0; i < s.size(); ++i)
    for (int c = 0; c < 3; ++c) f.rho.push_back(float(s.rho[i][c])), f.emission.push_back(float(s.emission[i][c]));
  std::vector<float> Bf(f.emission.begin(), f.emission.end());
  std::vector<gi::Color> Bd = s.emission;
  gi::Table table("Gauss-Seidel in float and in double: relative residual per sweep",
                  {{"sweep"}, {"float", 2, gi::Format::Scientific}, {"double", 2, gi::Format::Scientific}});
  for (int sweep = 1; sweep <= 30; ++sweep) {
    gi::gauss_seidel_sweep_float(f, Bf);
    gi::gauss_seidel_sweep(s, Bd);
    if (sweep % 3 == 0) {
      const std::vector<gi::Color> r = gi::residual(s, Bd);
      double r2 = 0, e2 = 0;
      for (int i = 0; i < s.size(); ++i) r2 += gi::length_squared(r[i]), e2 += gi::length_squared(s.emission[i]);
      table.add_row({sweep, gi::relative_residual(f, Bf), std::sqrt(r2 / e2)});
    }
  }
  lesson.table(table, "precision");
}

// 5. One Gauss-Seidel sweep over an n x n float matrix against the memory's speed.
void bandwidth(int n, gi::Lesson& lesson) {
  gi::FloatSystem s{n, std::vector<float>(static_cast<std::size_t>(n) * n), std::vector<float>(3 * n, 0.5f),
                    std::vector<float>(3 * n)};
  gi::Rng rng(12);
  for (float& f : s.F) f = static_cast<float>(2.0 / n * rng.uniform());  // rows sum to about 1, like a closed room
  for (float& e : s.emission) e = static_cast<float>(rng.uniform());
  std::vector<float> B(s.emission);
  const double bytes = 4.0 * n * n;
  std::vector<double> read, sweep;
  float sink = 0;
  for (int run = 0; run < 3; ++run) {
    gi::Timer timer;
    sink += gi::sum_all(s.F);  // the bound: just read every form factor
    read.push_back(timer.seconds());
    timer.restart();
    gi::gauss_seidel_sweep_float(s, B);
    sweep.push_back(timer.seconds());
  }
  const double bound = bytes / gi::median(read) / 1e9, achieved = bytes / gi::median(sweep) / 1e9;
  gi::Table table("One Gauss-Seidel sweep over a dense " + std::to_string(n) + " x " + std::to_string(n) +
                      " float matrix (" + gi::format_number(bytes / 1e6, 0, gi::Format::Fixed) + " MB), one thread, median of 3",
                  {{"pass"}, {"ms", 1}, {"GB/s", 2}, {"x the bound", 2}});
  table.add_row({"read every F_ij (the memory-bandwidth bound)", 1e3 * gi::median(read), bound, 1.0});
  table.add_row({"Gauss-Seidel sweep, 3 channels", 1e3 * gi::median(sweep), achieved, gi::median(sweep) / gi::median(read)});
  lesson.table(table, "bandwidth");
  if (!std::isfinite(sink)) std::cout << "(checksum " << sink << ")\n";  // keeps the read from being optimised away
}

}  // namespace lesson12
