#include "gi/twopass/radiosity_pass.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/twopass/shadow_rays.hpp"

namespace gi {

namespace {

// D_i = rho_i (1/A_i) integral over element i of H(x) dx, by strata^2 jittered points
// of its bilinear map, each weighted by the map's area element (so a trapezoid's wide
// end counts for more).
std::vector<Color> direct_by_shadow_rays(const Mesh& mesh, const EyeWorld& eye, const RadiosityPassSettings& s,
                                         int threads) {
  const ShadowRayLights lights = shadow_ray_lights(mesh, s.light_cells);
  const int m = s.receiver_strata;
  std::vector<Color> D(mesh.elements.size());
  parallel_for(static_cast<int>(mesh.elements.size()), threads, [&](int i) {
    const Element& e = mesh.elements[i];
    const auto& c = e.shape.corners;
    Rng rng(s.seed, static_cast<std::uint64_t>(i));
    const double lift = 1e-7 * length(c[2] - c[0]);  // off its own triangles
    Color H(0.0);
    double weight = 0;
    for (int k = 0; k < m * m; ++k) {
      const double u = (k % m + rng.uniform()) / m, v = (k / m + rng.uniform()) / m;
      const vec3 ds = (1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]);
      const vec3 dt = (1 - u) * (c[3] - c[0]) + u * (c[2] - c[1]);
      const double dA = length(cross(ds, dt));
      H += dA * irradiance_by_shadow_rays(eye, lights, bilinear(c, u, v) + lift * e.shape.normal, e.shape.normal, rng);
      weight += dA;
    }
    D[i] = mesh.reflectance(e) * H / weight;
  });
  return D;
}

}  // namespace

RadiosityPass radiosity_pass(const TwoPassScene& scene, const RadiosityPassSettings& settings, int threads) {
  if (settings.receiver_strata < 1 || settings.receiver_strata > 16)
    throw std::invalid_argument("radiosity pass: receiver strata must lie in [1, 16]");
  if (!(settings.tolerance > 0)) throw std::invalid_argument("radiosity pass: the tolerance must be positive");
  Mesh mesh = make_mesh(scene.surfaces, {patch_size_for(scene.surfaces, settings.elements, 1), 1});
  RadiosityPass pass;
  FormFactorSettings ff = settings.form_factors;
  if (ff.method == FormFactorMethod::Hemicube && ff.hemicube_resolution == 0)
    ff.hemicube_resolution = hemicube_resolution_for(mesh);
  check(ff);
  pass.hemicube_resolution = ff.method == FormFactorMethod::Hemicube ? ff.hemicube_resolution : 0;

  Timer timer;
  const EyeWorld eye = make_eye_world(mesh, scene.spheres);
  std::vector<Color> D = direct_by_shadow_rays(mesh, eye, settings, threads);
  pass.direct_seconds = timer.seconds();

  timer.restart();
  const FormFactorScene receivers(element_shapes(mesh));
  const RadiositySystem system = make_system(mesh, FormFactorMatrix{});
  SolverOptions options;
  options.tolerance = settings.tolerance;
  options.max_steps = 1000 * system.size();
  // A patch shoots many times before the unshot energy is small: its row is computed
  // the first time and kept (a hemicube per shot would cost ten times as much).
  const ShooterRow hemicube_row = patch_shooter(receivers, mesh, ff);
  std::vector<std::vector<double>> rows(mesh.patches.size());
  const ShooterRow row = [&](int p) {
    if (rows[p].empty()) rows[p] = hemicube_row(p);
    return rows[p];
  };
  const SolverResult solution = solve_progressive(indirect_system(system, D), mesh, row, options);
  pass.solve_seconds = timer.seconds();
  pass.status = solution.status;
  pass.shots = solution.history.back().step;
  pass.handoff = make_handoff(std::move(mesh), with_emission(system, solution.B), std::move(D));
  return pass;
}

}  // namespace gi
