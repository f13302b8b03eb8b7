#include "gi/radiosity/system/shooting_furnace.hpp"

#include <algorithm>
#include <cmath>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/system/solvers.hpp"

namespace gi {

namespace {

constexpr double furnace_rho = 0.5, furnace_E = 1.0;

double worst_furnace_error(const std::vector<Color>& B) {
  const double exact = furnace_E / (1 - furnace_rho);
  double worst = 0;
  for (const Color& b : B)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] / exact - 1));
  return worst;
}

// How far the matrix is from a closed room's sums and from reciprocity.
void measure(const RadiositySystem& s, ShootingFurnaceRow& row) {
  const int n = s.size();
  double differ = 0, total = 0;
  for (int i = 0; i < n; ++i) {
    double sum = 0, column = 0;
    for (int j = 0; j < n; ++j) {
      sum += s.F(i, j);
      column += s.area[j] * s.F(j, i) / s.area[i];
      differ += std::abs(s.area[i] * s.F(i, j) - s.area[j] * s.F(j, i));
      total += s.area[i] * s.F(i, j) + s.area[j] * s.F(j, i);
    }
    row.row_sums = std::max(row.row_sums, std::abs(sum - 1));
    row.column_sums = std::max(row.column_sums, std::abs(column - 1));
  }
  row.nonreciprocal = total > 0 ? differ / total : 0;
}

}  // namespace

std::vector<ShootingFurnaceRow> shooting_furnace(int elements, int threads) {
  RadiosityScene scene = closed_box(1.0);
  for (Surface& f : scene.surfaces) f.reflectance = Color(furnace_rho), f.emission = Color(furnace_E);
  const Mesh mesh = make_mesh(scene.surfaces, {patch_size_for(scene.surfaces, elements, 1), 1});
  const FormFactorScene shapes(element_shapes(mesh));
  FormFactorSettings hemicube, monte_carlo, analytic;
  monte_carlo.method = FormFactorMethod::MonteCarlo;
  monte_carlo.rays = 256;
  analytic.method = FormFactorMethod::Analytic;
  SolverOptions options;
  options.tolerance = 1e-9;
  options.max_steps = 1'000'000;
  std::vector<ShootingFurnaceRow> rows;
  for (const FormFactorSettings& settings : {hemicube, monte_carlo, analytic}) {
    const RadiositySystem s = make_system(mesh, form_factor_matrix(shapes, settings, threads));
    ShootingFurnaceRow base;
    base.form_factors = name(settings.method);
    measure(s, base);
    // The shooter's own row, as if computed when it shoots (here read from the matrix);
    // and the receivers' rows, column p of F turned into a row by reciprocity's formula,
    // F_pj = F_jp A_j / A_p, so that j receives exactly rho_j F_jp dB_p.
    const ShooterRow own = [&](int p) {
      std::vector<double> f(s.size());
      for (int j = 0; j < s.size(); ++j) f[j] = s.F(p, j);
      return f;
    };
    const ShooterRow receivers = [&](int p) {
      std::vector<double> f(s.size());
      for (int j = 0; j < s.size(); ++j) f[j] = s.F(j, p) * s.area[j] / s.area[p];
      return f;
    };
    const std::vector<std::pair<std::string, SolverResult>> solved = {
        {"gathering (Gauss-Seidel), own rows", solve_gauss_seidel(s, options)},
        {"shooting, the shooter's row", solve_progressive(s, mesh, own, options)},
        {"shooting, the receivers' rows", solve_progressive(s, mesh, receivers, options)}};
    for (const auto& [solver, result] : solved) {
      ShootingFurnaceRow row = base;
      row.solver = solver;
      row.furnace = worst_furnace_error(result.B);
      row.steps = result.history.back().step;
      rows.push_back(row);
    }
  }
  return rows;
}

Table shooting_furnace_table(const std::vector<ShootingFurnaceRow>& rows) {
  Table table("Shooting in a white furnace (closed box, E = 1, rho = 0.5, B = 2): shooting hands each receiver "
              "the shooter's F by reciprocity, A_p F_pj / A_j",
              {{"form factors"}, {"rows: max |sum - 1|", 1, Format::Scientific},
               {"receivers: max |sum - 1|", 1, Format::Scientific}, {"non-reciprocal", 1, Format::Scientific},
               {"solver"}, {"steps"}, {"furnace: max |B/2 - 1|", 1, Format::Scientific}});
  for (const ShootingFurnaceRow& r : rows)
    table.add_row({r.form_factors, r.row_sums, r.column_sums, r.nonreciprocal, r.solver, r.steps, r.furnace});
  return table;
}

}  // namespace gi
