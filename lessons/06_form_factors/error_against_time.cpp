// Lesson 06, step 5: error against time (studies.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "configurations.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/table.hpp"
#include "studies.hpp"

namespace lesson06 {

// Error against time for each method over its parameter, on two unit squares at d = 1.
void error_against_time(int most_rays, gi::Lesson& lesson) {
  const gi::FormFactorScene scene(facing_squares(1));
  const double exact = gi::ff_parallel_rectangles(1, 1, 1);
  gi::Table table("Error against time, parallel squares d = 1 (exact: ff_parallel_rectangles; Monte Carlo: RMS of 16 "
                  "estimates, F their mean)",
                  {{"method"}, {"parameter"}, {"F", 6}, {"rel. error", 2, gi::Format::Scientific}, {"us", 1}});
  std::vector<gi::Series> curves;
  const auto sweep = [&](FormFactorMethod m, const std::string& parameter, const std::vector<int>& values,
                         const std::function<void(gi::FormFactorSettings&, int)>& set) {
    gi::Series series{gi::name(m), {}, {}};
    for (int v : values) {
      gi::FormFactorSettings s;
      s.method = m;
      set(s, v);
      // Monte Carlo's error is noise: its root mean square over 16 independent
      // estimates, not the luck of one.
      const int estimates = m == FormFactorMethod::MonteCarlo ? 16 : 1;
      double square = 0, us = 0, value = 0;
      for (int r = 0; r < estimates; ++r) {
        const auto [f, t] = evaluate(scene, s, r, 1);
        square += (f - exact) * (f - exact) / estimates, us += t / estimates, value += f / estimates;
      }
      const double error = std::max(std::sqrt(square) / exact, 1e-16);
      table.add_row({gi::name(m), parameter.empty() ? "-" : parameter + std::to_string(v), value, error, us});
      series.x.push_back(us);
      series.y.push_back(error);
    }
    curves.push_back(series);
  };
  sweep(FormFactorMethod::Differential, "", {0}, [](gi::FormFactorSettings&, int) {});
  sweep(FormFactorMethod::Analytic, "tolerance 1e-", {2, 4, 6, 8, 10, 12},
        [](auto& s, int v) { s.tolerance = std::pow(10.0, -v); });
  std::vector<int> ray_counts;  // none a square, to show that only the count matters
  for (int rays = 100; rays <= most_rays; rays *= 10) ray_counts.push_back(rays);
  sweep(FormFactorMethod::MonteCarlo, "rays ", ray_counts, [](auto& s, int v) { s.rays = v; });
  sweep(FormFactorMethod::Hemicube, "res ", {10, 20, 50, 100, 200, 400}, [](auto& s, int v) { s.hemicube_resolution = v; });
  lesson.table(table, "error_vs_time");
  curves.front().mark = gi::Mark::Points;
  lesson.chart({"Form factor of two unit squares at d = 1: error against time", "time per evaluation (us)",
                "relative error", true, true, curves},
               "error_vs_time");
}

}  // namespace lesson06
