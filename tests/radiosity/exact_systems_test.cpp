// Radiosity systems with exact answers, solved with the analytic method's form factors
// by every solver: each must reproduce the exact B to 1e-8 relative.
//  - The six-patch cube: F from the closed forms (opposite faces: parallel squares;
//    neighbours: perpendicular squares sharing an edge), unequal reflectances, the
//    6 x 6 system solved by elimination in gi::wide
//    (its round-off, 1e-15, far below the 1e-8 asked of the solvers).
//  - The furnace: a closed box of 24 elements with uniform rho and E, where
//    B = E / (1 - rho) wherever every row of F sums to 1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "gi/core/wide_float.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/radiosity_system.hpp"
#include "gi/radiosity/system/solvers.hpp"

using gi::Color;

namespace {

gi::FormFactorSettings analytic() {
  gi::FormFactorSettings s;
  s.method = gi::FormFactorMethod::Analytic;
  return s;
}

// Every solver on `system`, progressive refinement shooting analytic rows from the
// mesh's patches.
std::vector<gi::SolverResult> every_solver(const gi::RadiositySystem& system, const gi::Mesh& mesh) {
  gi::SolverOptions options;
  options.tolerance = 1e-13;
  options.max_steps = 100000;
  // A patch shoots many times: its row is computed once, when it first shoots.
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  std::vector<std::vector<double>> rows(mesh.patches.size());
  const gi::ShooterRow row = [&](int p) {
    if (rows[p].empty()) rows[p] = gi::form_factor_row(scene, mesh.patches[p].shape, p, analytic());
    return rows[p];
  };
  return {gi::solve_direct(system, options),       gi::solve_jacobi(system, options),
          gi::solve_gauss_seidel(system, options), gi::solve_gauss_seidel(system, options, 1.3),
          gi::solve_southwell(system, options),    gi::solve_progressive(system, mesh, row, options)};
}

void expect_close(const std::vector<gi::SolverResult>& results, const std::vector<Color>& exact) {
  for (const gi::SolverResult& r : results) {
    EXPECT_EQ(r.status, gi::SolveStatus::Converged) << r.method;
    for (std::size_t i = 0; i < exact.size(); ++i)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.B[i][c], exact[i][c], 1e-8 * exact[i][c]) << r.method << " " << i;
  }
}

}  // namespace

TEST(ExactSystems, TheSixPatchCube) {
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {1e30, 1});
  ASSERT_EQ(mesh.elements.size(), 6u);
  gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), analytic(), 2));
  system.rho = {Color(0.3, 0.5, 0.9), Color(0.5), Color(0.7, 0.2, 0.1), Color(0.6), Color(0.4, 0.8, 0.6), Color(0.8)};
  system.emission = {Color(0), Color(1, 2, 3), Color(0), Color(0), Color(0.5), Color(0)};
  // The exact system: F between opposite faces and between neighbours, in closed form.
  const double opposite = gi::ff_parallel_rectangles(1, 1, 1), neighbour = gi::ff_perpendicular_rectangles(1, 1, 1);
  std::vector<Color> exact(6);
  for (int c = 0; c < 3; ++c) {
    std::array<std::array<gi::wide, 7>, 6> K{};  // (I - R F | E)
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const double facing = gi::dot(mesh.elements[i].shape.normal, mesh.elements[j].shape.normal);
        const double F = i == j ? 0.0 : facing < -0.5 ? opposite : neighbour;
        K[i][j] = (i == j) - static_cast<gi::wide>(system.rho[i][c]) * F;
      }
      K[i][6] = system.emission[i][c];
    }
    for (int k = 0; k < 6; ++k)  // Gauss-Jordan; diagonally dominant, no pivoting needed
      for (int i = 0; i < 6; ++i)
        if (i != k) {
          const gi::wide factor = K[i][k] / K[k][k];
          for (int j = k; j < 7; ++j) K[i][j] -= factor * K[k][j];
        }
    for (int i = 0; i < 6; ++i) exact[i][c] = static_cast<double>(K[i][6] / K[i][i]);
  }
  expect_close(every_solver(system, mesh), exact);
}

TEST(ExactSystems, TheFurnace) {
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 1});
  ASSERT_EQ(mesh.elements.size(), 24u);
  gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), analytic(), 2));
  system.rho.assign(24, Color(0.7, 0.5, 0.9));
  system.emission.assign(24, Color(1.0));
  expect_close(every_solver(system, mesh), std::vector<Color>(24, Color(1 / 0.3, 1 / 0.5, 1 / 0.1)));
}
