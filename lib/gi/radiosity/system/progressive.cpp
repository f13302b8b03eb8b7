#include "gi/radiosity/system/progressive.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

void shoot(const Patch& patch, const std::vector<double>& F_p, const std::vector<double>& area,
           const std::vector<Color>& rho, std::vector<Color>& B, std::vector<Color>& unshot) {
  // BEGIN EXERCISE 11.1 a progressive-refinement shot
  Color unshot_p(0.0);
  for (int e = patch.first_element; e < patch.first_element + patch.element_count; ++e) {
    unshot_p += unshot[e] * area[e];
    unshot[e] = Color(0.0);  // shot: it must not be shot again
  }
  unshot_p /= patch.shape.area;
  for (std::size_t j = 0; j < area.size(); ++j) {
    if (F_p[j] == 0) continue;
    const Color received = rho[j] * unshot_p * (F_p[j] * patch.shape.area / area[j]);  // F_jp by reciprocity
    B[j] += received;
    unshot[j] += received;
  }
  // END EXERCISE 11.1
}

Color ambient_term(const std::vector<double>& area, const std::vector<Color>& rho, const std::vector<Color>& unshot) {
  // BEGIN EXERCISE 11.2 the ambient term
  double total_area = 0;
  Color unshot_power(0.0), reflectance(0.0);
  for (std::size_t i = 0; i < area.size(); ++i) {
    total_area += area[i];
    unshot_power += unshot[i] * area[i];
    reflectance += rho[i] * area[i];
  }
  const Color rho_avg = reflectance / total_area;
  const Color r_total = 1.0 / (Color(1.0) - rho_avg);  // 1 + rho + rho^2 + ...
  return r_total * unshot_power / total_area;
  // END EXERCISE 11.2
}

std::vector<Color> with_ambient(const std::vector<double>& area, const std::vector<Color>& rho,
                                const std::vector<Color>& B, const std::vector<Color>& unshot) {
  const Color ambient = ambient_term(area, rho, unshot);
  std::vector<Color> shown(B.size());
  for (std::size_t i = 0; i < B.size(); ++i) shown[i] = B[i] + rho[i] * ambient;
  return shown;
}

ShooterRow patch_shooter(const FormFactorScene& receivers, const Mesh& mesh, const FormFactorSettings& settings) {
  check(settings);
  return [&receivers, &mesh, settings](int p) { return form_factor_row(receivers, mesh.patches[p].shape, p, settings); };
}

int choose_shooter(const std::vector<Patch>& patches, const std::vector<double>& area,
                   const std::vector<Color>& unshot) {
  // BEGIN EXERCISE 11.3 choosing the shooter: the most unshot power
  int shooter = 0;
  double most = -1;
  for (int p = 0; p < static_cast<int>(patches.size()); ++p) {
    const Patch& patch = patches[p];
    Color power(0.0);  // sum_e dB_e A_e, per channel
    for (int e = patch.first_element; e < patch.first_element + patch.element_count; ++e)
      power += unshot[e] * area[e];
    const double total = power.x + power.y + power.z;
    if (total > most) most = total, shooter = p;
  }
  return shooter;
  // END EXERCISE 11.3
}

SolverResult solve_progressive(const RadiositySystem& s, const Mesh& mesh, const ShooterRow& row,
                               const SolverOptions& options) {
  SolverMonitor monitor("progressive", s, options, true);
  std::vector<Color> B = s.emission, unshot = s.emission;
  for (int step = 1;; ++step) {
    const int shooter = choose_shooter(mesh.patches, s.area, unshot);
    shoot(mesh.patches[shooter], row(shooter), s.area, s.rho, B, unshot);
    if (monitor.stop_after(step, B, unshot)) break;
  }
  return monitor.finish(std::move(B), std::move(unshot));
}

}  // namespace gi
