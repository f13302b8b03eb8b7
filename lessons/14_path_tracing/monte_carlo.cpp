// Lesson 14, step 1: Monte Carlo on closed forms (monte_carlo.hpp).
#include "monte_carlo.hpp"

#include <cmath>

#include "gi/core/rng.hpp"
#include "gi/core/sampling.hpp"
#include "gi/report/table.hpp"

namespace lesson14 {

void monte_carlo_warm_up(const Settings& s, gi::Lesson& lesson) {
  gi::Table table("Monte Carlo: RMS error of 400 estimates with N samples (closed forms: 2 and 2.5 pi)",
                  {{"N"},
                   {"1-D, uniform", 2, gi::Format::Scientific},
                   {"sky, uniform", 2, gi::Format::Scientific},
                   {"sky, cosine", 2, gi::Format::Scientific}});
  gi::Rng rng(s.seed, 14);
  const auto sky = [](const gi::vec3& w) { return 1 + 3 * w.z * w.z; };
  for (int n = 1; n <= 4096; n *= 4) {
    double e1 = 0, e2 = 0, e3 = 0;
    for (int trial = 0; trial < 400; ++trial) {
      double line = 0, uniform = 0, cosine = 0;
      for (int k = 0; k < n; ++k) {
        line += std::sin(gi::pi * rng.uniform()) * gi::pi;  // f(x) / p(x), p = 1 / pi
        const gi::vec3 u = gi::sample_uniform_hemisphere({rng.uniform(), rng.uniform()});
        uniform += sky(u) * u.z / gi::uniform_hemisphere_pdf();
        const gi::vec3 c = gi::sample_cosine_hemisphere({rng.uniform(), rng.uniform()});
        cosine += sky(c) * c.z / gi::cosine_hemisphere_pdf(c.z);
      }
      e1 += std::pow(line / n - 2, 2), e2 += std::pow(uniform / n - 2.5 * gi::pi, 2);
      e3 += std::pow(cosine / n - 2.5 * gi::pi, 2);
    }
    table.add_row({n, std::sqrt(e1 / 400), std::sqrt(e2 / 400), std::sqrt(e3 / 400)});
  }
  lesson.table(table, "monte_carlo");
}

}  // namespace lesson14
