#include "gi/radiosity/system/solvers.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

using gi::Color;

namespace {

// A "furnace": n elements of equal area, each seeing every other equally, F_ij =
// 1/(n-1): a closed room. With uniform rho and E the answer is B = E / (1 - rho).
gi::RadiositySystem furnace(int n, double rho, double e) {
  gi::RadiositySystem s;
  s.area.assign(n, 1.0);
  s.rho.assign(n, Color(rho));
  s.emission.assign(n, Color(e));
  s.F = {n, std::vector<double>(static_cast<std::size_t>(n) * n, 1.0 / (n - 1))};
  for (int i = 0; i < n; ++i) s.F(i, i) = 0;
  return s;
}

// The Cornell box at ~150 elements with hemicube form factors.
struct Cornell {
  gi::Mesh mesh;
  gi::RadiositySystem system;
};
const Cornell& cornell() {
  static const Cornell c = [] {
    const gi::RadiosityScene scene = gi::cornell_box();
    gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 150, 1), 1});
    gi::FormFactorMatrix F = gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), 50, 2);
    gi::RadiositySystem system = gi::make_system(mesh, std::move(F));
    return Cornell{std::move(mesh), std::move(system)};
  }();
  return c;
}

double max_difference(const std::vector<Color>& a, const std::vector<Color>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, gi::max_component(glm::abs(a[i] - b[i])));
  return d;
}

}  // namespace

TEST(Solvers, FurnaceHasTheClosedFormAnswer) {
  const gi::RadiositySystem s = furnace(12, 0.7, 2.0);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  for (const gi::SolverResult& r : {gi::solve_direct(s, options), gi::solve_jacobi(s, options),
                                    gi::solve_gauss_seidel(s, options), gi::solve_gauss_seidel(s, options, 1.3),
                                    gi::solve_southwell(s, options)}) {
    EXPECT_EQ(r.status, gi::SolveStatus::Converged) << r.method;
    for (const Color& b : r.B) EXPECT_NEAR(b.y, 2.0 / 0.3, 1e-9) << r.method;
  }
}

// Residuals and errors are relative, so a light 1e-300 times dimmer (radiosities whose
// squares are 0 in double) must give the same history, step by step, as a light of 1;
// and a light 2^-900 times dimmer (a power of two: every number scales exactly) the
// very same numbers.
TEST(Solvers, RelativeNumbersDoNotDependOnTheLightsScale) {
  const gi::RadiositySystem& bright = cornell().system;
  const gi::SolverResult reference = gi::solve_direct(bright);
  for (const double k : {1e-300, std::ldexp(1.0, -900), 1e300}) {
    gi::RadiositySystem dim = bright;
    for (Color& e : dim.emission) e *= k;
    std::vector<Color> dim_reference = reference.B;
    for (Color& b : dim_reference) b *= k;
    gi::SolverOptions options, dim_options;
    options.tolerance = dim_options.tolerance = 1e-6;
    options.reference = &reference.B;
    dim_options.reference = &dim_reference;
    const gi::SolverResult a = gi::solve_gauss_seidel(bright, options), b = gi::solve_gauss_seidel(dim, dim_options);
    EXPECT_EQ(b.status, gi::SolveStatus::Converged) << k;
    ASSERT_EQ(a.history.size(), b.history.size()) << k;
    const double tolerance = std::ldexp(1.0, std::ilogb(k)) == k ? 0 : 1e-9;  // a power of two: exact
    for (std::size_t i = 0; i < a.history.size(); ++i) {
      EXPECT_NEAR(b.history[i].residual_2, a.history[i].residual_2, tolerance * a.history[i].residual_2) << k;
      EXPECT_NEAR(b.history[i].error, a.history[i].error, tolerance * a.history[i].error + 1e-15) << k;
    }
  }
}

TEST(Solvers, TwoPatchesSolvedByHand) {
  // B1 = E1 + rho1 F12 B2, B2 = rho2 F21 B1 with E2 = 0.
  gi::RadiositySystem s;
  s.area = {1, 2};
  s.rho = {Color(0.5), Color(0.8)};
  s.emission = {Color(1), Color(0)};
  s.F = {2, {0, 0.4, 0.2, 0}};
  const double b1 = 1 / (1 - 0.5 * 0.4 * 0.8 * 0.2), b2 = 0.8 * 0.2 * b1;
  const gi::SolverResult r = gi::solve_direct(s);
  EXPECT_NEAR(r.B[0].x, b1, 1e-14);
  EXPECT_NEAR(r.B[1].x, b2, 1e-14);
}

TEST(Solvers, AllAgreeOnTheCornellBox) {
  const gi::RadiositySystem& s = cornell().system;
  const gi::SolverResult direct = gi::solve_direct(s);
  gi::SolverOptions options;
  options.tolerance = 1e-10;
  options.max_steps = 200000;
  options.reference = &direct.B;
  double scale = 0;
  for (const Color& b : direct.B) scale = std::max(scale, gi::max_component(b));
  for (const gi::SolverResult& r : {gi::solve_jacobi(s, options), gi::solve_gauss_seidel(s, options),
                                    gi::solve_gauss_seidel(s, options, 1.2), gi::solve_southwell(s, options)}) {
    EXPECT_EQ(r.status, gi::SolveStatus::Converged) << r.method;
    EXPECT_LT(max_difference(r.B, direct.B), 1e-8 * scale) << r.method;
    EXPECT_LT(r.history.back().error, 1e-8) << r.method;
  }
}

TEST(Solvers, JacobiSumsTheNeumannSeries) {
  const gi::RadiositySystem& s = cornell().system;
  // E + RFE + (RF)^2 E, term by term.
  std::vector<Color> term = s.emission, sum = s.emission;
  for (int k = 1; k <= 2; ++k) {
    std::vector<Color> next(s.size(), Color(0.0));
    for (int i = 0; i < s.size(); ++i)
      for (int j = 0; j < s.size(); ++j) next[i] += s.rho[i] * s.F(i, j) * term[j];
    term = next;
    for (int i = 0; i < s.size(); ++i) sum[i] += term[i];
  }
  gi::SolverOptions options;
  options.max_steps = 2;
  options.tolerance = 0;
  EXPECT_LT(max_difference(gi::solve_jacobi(s, options).B, sum), 1e-9);
}

TEST(Solvers, GaussSeidelNeedsFewerSweepsThanJacobi) {
  const gi::RadiositySystem& s = cornell().system;
  gi::SolverOptions options;
  options.tolerance = 1e-8;
  const auto jacobi = gi::solve_jacobi(s, options), gauss_seidel = gi::solve_gauss_seidel(s, options);
  EXPECT_LT(gauss_seidel.history.size() * 3, jacobi.history.size() * 2);
}

TEST(Solvers, SouthwellKeepsItsResidualUpToDate) {
  const gi::RadiositySystem& s = cornell().system;
  std::vector<Color> B(s.size(), Color(0.0)), r = s.emission;
  for (int step = 0; step < 300; ++step) gi::southwell_step(s, B, r);
  EXPECT_LT(max_difference(r, gi::residual(s, B)), 1e-9);
}

TEST(Solvers, DivergenceIsReportedNotHidden) {
  const gi::RadiositySystem s = furnace(8, 1.3, 1.0);  // reflects more than it receives
  gi::SolverOptions options;
  options.max_steps = 100000;
  for (const gi::SolverResult& r : {gi::solve_jacobi(s, options), gi::solve_gauss_seidel(s, options),
                                    gi::solve_southwell(s, options)}) {
    EXPECT_EQ(r.status, gi::SolveStatus::Diverged) << r.method;
    for (const Color& b : r.B) EXPECT_TRUE(gi::is_finite(b)) << r.method << ": stopped before overflow";
  }
}

TEST(Solvers, ProgressiveConvergesAndItsUnshotEnergyFalls) {
  const Cornell& c = cornell();
  const gi::SolverResult direct = gi::solve_direct(c.system);
  gi::SolverOptions options;
  options.tolerance = 1e-6;
  options.max_steps = 100000;
  options.reference = &direct.B;
  // Shooting uses F_jp = F_pj A_p / A_j. The hemicube matrix is not reciprocal (lesson
  // 07), so to solve the very system the direct solver solves, p's row is made from
  // its column: F_pj = F_jp A_j / A_p.
  const gi::RadiositySystem& s = c.system;
  const auto row = [&](int p) {
    std::vector<double> f(s.size());
    for (int j = 0; j < s.size(); ++j) f[j] = s.F(j, p) * s.area[j] / s.area[p];
    return f;
  };
  const gi::SolverResult r = gi::solve_progressive(c.system, c.mesh, row, options);
  EXPECT_EQ(r.status, gi::SolveStatus::Converged);
  EXPECT_LT(r.history.back().error, 1e-5);
}

TEST(Solvers, EveryShotLowersTheUnshotEnergyWhenFormFactorsAreReciprocal) {
  // 24 equal elements of a closed box, each seeing the others equally: a shot of
  // power P leaves rho P unshot, so the unshot energy must fall at every step.
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 1});
  const gi::RadiositySystem uniform = furnace(24, 0.6, 1.0);
  gi::RadiositySystem s = gi::make_system(mesh, uniform.F);
  s.emission.assign(24, Color(0));
  s.emission[5] = Color(1.0);
  const auto row = [&](int p) { return std::vector<double>(s.F.values.begin() + p * 24, s.F.values.begin() + (p + 1) * 24); };
  gi::SolverOptions options;
  options.tolerance = 1e-9;
  const gi::SolverResult r = gi::solve_progressive(s, mesh, row, options);
  EXPECT_EQ(r.status, gi::SolveStatus::Converged);
  for (std::size_t k = 1; k < r.history.size(); ++k) EXPECT_LT(r.history[k].unshot, r.history[k - 1].unshot);
  EXPECT_LT(max_difference(r.B, gi::solve_direct(s).B), 1e-8);
}

TEST(Solvers, AmbientTermMakesTheFirstFurnacePictureExact) {
  // Before any shot B = E and all of E is unshot: B + rho * ambient = E / (1 - rho).
  const gi::RadiositySystem s = furnace(6, 0.6, 1.0);
  const std::vector<Color> shown = gi::with_ambient(s.area, s.rho, s.emission, s.emission);
  for (const Color& b : shown) EXPECT_NEAR(b.z, 1.0 / 0.4, 1e-12);
}

TEST(Solvers, EnergyIsConservedInAClosedRoom) {
  // Emitted power = absorbed power: sum A_i E_i = sum A_i (1 - rho_i) H_i, with the
  // irradiance H_i = (B_i - E_i) / rho_i. Hemicube rows sum to 1 + 1e-4 at res 100.
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.25, 1});
  const gi::RadiositySystem s = gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), 100, 2));
  const gi::SolverResult r = gi::solve_direct(s);
  double emitted = 0, absorbed = 0;
  for (int i = 0; i < s.size(); ++i) {
    emitted += s.area[i] * s.emission[i].x;
    absorbed += s.area[i] * (1 - s.rho[i].x) * (r.B[i].x - s.emission[i].x) / s.rho[i].x;
  }
  EXPECT_NEAR(absorbed, emitted, 2e-3 * emitted);
}

TEST(Solvers, ASingularSystemSaysSoWithOneHistoryRow) {
  // Two elements that see only each other, rho = 1: K = [[1, -1], [-1, 1]] has no
  // inverse (light would circle forever).
  gi::RadiositySystem s = furnace(2, 1.0, 1.0);
  gi::SolverOptions options;
  const std::vector<Color> reference(2, Color(1.0));
  options.reference = &reference;
  const gi::SolverResult r = gi::solve_direct(s, options);
  EXPECT_EQ(r.status, gi::SolveStatus::Singular);
  EXPECT_EQ(gi::status_name(r.status), "singular");
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_EQ(r.history.back().step, 1);
  EXPECT_TRUE(std::isnan(r.history.back().residual_2));
  EXPECT_TRUE(std::isnan(r.history.back().error)) << "no solution, no error to report";
  ASSERT_EQ(r.B.size(), 2u);
  EXPECT_TRUE(std::isnan(r.B[0].x));
  EXPECT_EQ(gi::stop_reason(r, "step"), "singular after 1 step");
}

TEST(Solvers, ARoomThatReflectsEverythingIsSingularDespiteRoundOff) {
  // Seven elements, F_ij = 1/6 (not exact in binary), rho = 1: the rows of K sum to
  // round-off, not 0, and elimination meets a pivot of ~1e-16 rather than 0. Dividing
  // by it made a B of ~1e16 reported as "stopped at the limit". Rho just below 1 is
  // nearly singular, not singular: B = E / (1 - rho) exactly as the closed form says.
  const gi::SolverResult r = gi::solve_direct(furnace(7, 1.0, 1.0));
  EXPECT_EQ(r.status, gi::SolveStatus::Singular);
  const gi::SolverResult near = gi::solve_direct(furnace(7, 1 - 1e-6, 1.0));
  ASSERT_EQ(near.status, gi::SolveStatus::Converged);
  for (const Color& B : near.B) EXPECT_NEAR(B.x, 1e6, 1e6 * 1e-7);
}

TEST(Solvers, HistoriesEndWhereTheSolverStopped) {
  // No interreflection (F = 0): one iteration reaches B = E exactly, residual 0, so a
  // solver asked for 30 iterations with tolerance 0 stops after 1, converged.
  gi::RadiositySystem s = furnace(3, 0.5, 1.0);
  std::fill(s.F.values.begin(), s.F.values.end(), 0.0);
  gi::SolverOptions options;
  options.tolerance = 0;
  options.max_steps = 30;
  for (const gi::SolverResult& r : {gi::solve_jacobi(s, options), gi::solve_gauss_seidel(s, options)}) {
    EXPECT_EQ(r.status, gi::SolveStatus::Converged) << r.method;
    ASSERT_EQ(r.history.size(), 1u) << r.method;
    ASSERT_NE(gi::find_step(r, 1), nullptr);
    EXPECT_EQ(gi::find_step(r, 1)->residual_2, 0.0);
    EXPECT_EQ(gi::find_step(r, 2), nullptr) << "step 2 never ran";
    EXPECT_EQ(gi::find_step(r, 0), nullptr);
    EXPECT_EQ(gi::stop_reason(r, "iteration"), "converged after 1 iteration");
  }
  // Recorded every 4th step: steps between are not found, the last one is.
  s = furnace(4, 0.5, 1.0);
  options.max_steps = 10;
  options.record_every = 4;
  const gi::SolverResult sparse = gi::solve_southwell(s, options);
  EXPECT_NE(gi::find_step(sparse, 8), nullptr);
  EXPECT_EQ(gi::find_step(sparse, 9), nullptr);
  EXPECT_NE(gi::find_step(sparse, 10), nullptr);
  EXPECT_EQ(gi::stop_reason(sparse, "step"), "stopped at the limit after 10 steps");
}

TEST(Solvers, ThePatchShooterIsThePatchsFormFactorRow) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 120, 2), 2});
  const gi::FormFactorScene receivers(gi::element_shapes(mesh));
  gi::FormFactorSettings settings;
  settings.hemicube_resolution = 20;
  const gi::ShooterRow row = gi::patch_shooter(receivers, mesh, settings);
  for (int p : {0, 7, static_cast<int>(mesh.patches.size()) - 1})
    EXPECT_EQ(row(p), gi::form_factor_row(receivers, mesh.patches[p].shape, p, settings)) << p;
  settings.hemicube_resolution = 21;
  EXPECT_THROW(gi::patch_shooter(receivers, mesh, settings), std::invalid_argument);
}

TEST(SpectralRadius, IsTheReflectanceOfAFurnace) {
  // Uniform rho and rows of F that sum to 1: R F = rho F, and a stochastic F has
  // spectral radius 1.
  const gi::RadiositySystem s = furnace(6, 0.6, 1.0);
  const gi::SpectralRadius r = gi::spectral_radius(s, 1);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.value(), 0.6, 1e-7);
}

TEST(SpectralRadius, TwoFacingPatchesAndARowOfZeros) {
  // R F = [[0, 0.5], [0.8, 0]] has eigenvalues +-sqrt(0.4): the shift copes with the
  // pair. A third element that gathers nothing (a row of zeros) changes nothing.
  gi::RadiositySystem s;
  s.area = {1, 1, 1};
  s.rho = {Color(0.5), Color(0.8), Color(0.7)};
  s.emission = {Color(1), Color(0), Color(0)};
  s.F = {3, {0, 1, 0, 1, 0, 0, 0, 0, 0}};
  const gi::SpectralRadius r = gi::spectral_radius(s, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.value(), std::sqrt(0.4), 1e-6);
  EXPECT_LE(r.lower, std::sqrt(0.4) + 1e-12);
}
