// Lesson 12, step 2: where the solvers crawl or fail (stability.hpp).
#include "stability.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/report/table.hpp"

namespace lesson12 {

// 2. Where solvers crawl or fail, and the spectral radius of RF that says how fast
// they go: Jacobi's error shrinks by rho(RF) per iteration, so it needs about
// ln(1e-6) / ln rho(RF) of them. rho(RF) is measured (power iteration, the largest over
// the channels), not assumed: it equals the reflectance only in a room that is truly
// closed, like the empty box; the Cornell box's "closed" front leaves floor elements
// under the blocks that see nothing and absorb all they get.
void stability(const gi::RadiositySystem& closed, const gi::RadiositySystem& open,
               const gi::RadiositySystem& empty, int threads, gi::Lesson& lesson) {
  const auto with_rho = [](gi::RadiositySystem s, double rho) {
    for (gi::Color& r : s.rho) r = gi::Color(rho);
    return s;
  };
  std::vector<std::pair<std::string, gi::RadiositySystem>> cases = {{"Cornell reflectances, closed", closed},
                                                                    {"Cornell reflectances, open front", open}};
  for (double rho : {0.9, 0.99, 0.999})
    cases.emplace_back("empty closed box, all rho = " + gi::format_number(rho, 3, gi::Format::Fixed),
                       with_rho(empty, rho));
  cases.emplace_back("Cornell closed, all rho = 0.999", with_rho(closed, 0.999));
  cases.emplace_back("Cornell open front, all rho = 0.99", with_rho(open, 0.99));
  cases.emplace_back("all rho = 1.05 (unphysical)", with_rho(closed, 1.05));
  gi::RadiositySystem rows = with_rho(closed, 0.95);
  for (double& f : rows.F.values) f *= 1.1;  // rows summing to 1.1: energy from nowhere
  cases.emplace_back("rho = 0.95, F rows sum to 1.1", std::move(rows));

  // Each case's spectral radius, Jacobi and Gauss-Seidel are independent of one
  // another: three tasks per case, shared among the threads (the slow cases near
  // rho = 1 take seconds each), each writing only its own slot.
  const int n = static_cast<int>(cases.size());
  std::vector<double> radius(n);
  std::vector<gi::SolverResult> jacobi(n), gauss_seidel(n);
  gi::SolverOptions options;
  options.tolerance = 1e-6;
  options.max_steps = 20000;
  gi::parallel_for(3 * n, threads, [&](int task) {
    const gi::RadiositySystem& s = cases[task / 3].second;
    if (task % 3 == 0) {
      for (int channel = 0; channel < 3; ++channel)
        radius[task / 3] = std::max(radius[task / 3], gi::spectral_radius(s, channel).value());
    } else if (task % 3 == 1) {
      jacobi[task / 3] = gi::solve_jacobi(s, options);
    } else {
      gauss_seidel[task / 3] = gi::solve_gauss_seidel(s, options);
    }
  });
  gi::Table table("Stability: iterations to ||r|| < 1e-6 (at most 20 000), or the failure detected",
                  {{"case"}, {"rho(RF)", 4}, {"ln(1e-6)/ln rho", 0}, {"Jacobi"}, {"Jacobi steps"}, {"Gauss-Seidel"},
                   {"G-S steps"}});
  for (int c = 0; c < n; ++c) {
    const gi::Cell predicted = radius[c] < 1 ? gi::Cell(std::log(1e-6) / std::log(radius[c])) : gi::Cell("-");
    table.add_row({cases[c].first, radius[c], predicted, gi::status_name(jacobi[c].status),
                   jacobi[c].history.back().step, gi::status_name(gauss_seidel[c].status),
                   gauss_seidel[c].history.back().step});
  }
  lesson.table(table, "stability");
}

}  // namespace lesson12
