// Lesson 06, steps 2 to 4: where each method fails (studies.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "configurations.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/item_buffer.hpp"
#include "gi/report/table.hpp"
#include "studies.hpp"

namespace lesson06 {
namespace {

// ---- Where each method fails ------------------------------------------------------
// One configuration per failure, each with an exact value: the relative error of every
// method, the analytic method's own estimate of its error beside its true error, and
// the old fixed Gauss rule over the sender (order 4) that the analytic method replaced.
std::vector<Case> failures() {
  const vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  return {
      {"near field: squares 1/20 apart", facing_squares(0.05), gi::ff_parallel_rectangles(1, 1, 0.05),
       "ff_parallel_rectangles"},
      {"far field: squares 100 apart", facing_squares(100), gi::ff_parallel_rectangles(1, 1, 100),
       "ff_parallel_rectangles (series)"},
      {"shared edge: perpendicular squares",
       {rectangle({0.5, 0, 0.5}, z, x, 1, 1), rectangle({0.5, 0.5, 0}, x, y, 1, 1)}, gi::ff_perpendicular_rectangles(1, 1, 1),
       "ff_perpendicular_rectangles"},
      {"thin strip: 1/100 wide, on the edge",
       {rectangle({0.5, 0, 0.005}, z, x, 0.01, 1), rectangle({0.5, 0.5, 0}, x, y, 1, 1)},
       gi::ff_perpendicular_rectangles(1, 0.01, 1), "ff_perpendicular_rectangles"},
      {"sub-cell receiver: 5 cm square 4 up",
       {rectangle({0, 0, 0}, z, x, 1, 1), rectangle({0.52, 4, 0.28}, x, z, 0.05, 0.05)},
       gi::ff_parallel_rectangles_offset(-0.5, 0.5, -0.5, 0.5, 0.495, 0.545, 0.255, 0.305, 4),
       "ff_parallel_rectangles_offset"}};
}

}  // namespace

void where_each_method_fails(const gi::FormFactorSettings& base, gi::Lesson& lesson) {
  gi::Table table("Where each method fails: relative error against the exact value (" + std::to_string(base.rays) +
                      " rays, hemicube " + std::to_string(base.hemicube_resolution) + ")",
                  {{"case"}, {"exact F", 3, gi::Format::Scientific}, {"differential", 2, gi::Format::Scientific},
                   {"Gauss 4x4", 2, gi::Format::Scientific}, {"analytic", 2, gi::Format::Scientific},
                   {"its estimate", 2, gi::Format::Scientific}, {"monte-carlo", 2, gi::Format::Scientific},
                   {"hemicube", 2, gi::Format::Scientific}, {"sub-cell?"}, {"exact from"}});
  for (const Case& f : failures()) {
    const gi::FormFactorScene scene(f.polygons);
    const auto error = [&](double value) { return std::abs(value - f.exact) / f.exact; };
    std::vector<gi::Cell> row{f.name, f.exact, error(evaluate(scene, with(FormFactorMethod::Differential, base)).first),
                              error(gi::form_factor_analytic(f.polygons[0], f.polygons[1], 4))};
    const gi::FormFactorRow analytic =
        gi::form_factor_row_with_diagnostics(scene, f.polygons[0], 0, with(FormFactorMethod::Analytic, base));
    row.push_back(std::max(error(analytic.F[1]), 1e-17));
    row.push_back(analytic.error[1] / f.exact);
    row.push_back(error(evaluate(scene, with(FormFactorMethod::MonteCarlo, base)).first));
    const gi::FormFactorRow hemicube =
        gi::form_factor_row_with_diagnostics(scene, f.polygons[0], 0, with(FormFactorMethod::Hemicube, base));
    row.push_back(error(hemicube.F[1]));
    row.push_back(hemicube.sub_cell_receivers ? "yes" : "no");
    row.push_back(f.source);
    table.add_row(row);
  }
  lesson.table(table, "failures");
}

void near_field(const gi::FormFactorSettings& base, gi::Lesson& lesson) {
  gi::Table table("As two unit squares approach: relative error of each method (exact: ff_parallel_rectangles)",
                  {{"distance", 2}, {"exact F", 4}, {"differential", 2, gi::Format::Scientific},
                   {"analytic", 2, gi::Format::Scientific}, {"monte-carlo", 2, gi::Format::Scientific},
                   {"hemicube", 2, gi::Format::Scientific}, {"plain point formula F", 3}});
  for (double d : {5.0, 2.0, 1.0, 0.5, 0.2, 0.1}) {
    const std::vector<gi::Polygon> squares = facing_squares(d);
    const gi::FormFactorScene scene(squares);
    const double exact = gi::ff_parallel_rectangles(1, 1, d);
    std::vector<gi::Cell> row{d, exact};
    for (FormFactorMethod m : methods) row.push_back(std::abs(evaluate(scene, with(m, base)).first - exact) / exact);
    // The lecture's formula itself, before the method scales rows that exceed 1.
    row.push_back(gi::form_factor_differential(squares[0].centre, squares[0].normal, squares[1].centre,
                                               squares[1].normal, squares[1].area, 1.0));
    table.add_row(row);
  }
  lesson.table(table, "near_field");
}

void hemicube_aliasing(gi::Lesson& lesson) {
  // A 5 cm square ever farther above a unit square's centre, a little off-axis. The
  // reference is the contour integral from that centre: exactly what a hemicube
  // estimates, so the error left is the cells' alone.
  gi::Table table("Hemicube aliasing: a 5 cm square at distance d (relative error against the exact point value)",
                  {{"d", 1}, {"exact F", 2, gi::Format::Scientific}, {"res 50", 2, gi::Format::Scientific},
                   {"res 100", 2, gi::Format::Scientific}, {"res 200", 2, gi::Format::Scientific},
                   {"res 400", 2, gi::Format::Scientific}, {"cells at 100", 2}});
  for (double d : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    const std::vector<gi::Polygon> polygons = {rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1),
                                               rectangle({0.13 * d, d, 0.07 * d}, {1, 0, 0}, {0, 0, 1}, 0.05, 0.05)};
    const gi::FormFactorScene scene(polygons);
    const double exact = gi::form_factor_point_to_polygon(polygons[0].centre, polygons[0].normal, polygons[1]);
    std::vector<gi::Cell> row{d, exact};
    for (int res : {50, 100, 200, 400}) {
      gi::FormFactorSettings s;
      s.hemicube_resolution = res;
      row.push_back(std::abs(evaluate(scene, s).first - exact) / exact);
    }
    // How many cells the square's image covers at resolution 100: under one, it is
    // counted whole or not at all (the row's sub-cell receivers).
    gi::ItemBuffer buffer;
    gi::render_item_buffer(polygons, gi::lifted_centre(polygons[0]), polygons[0].normal, 100, buffer);
    row.push_back(buffer.footprint[1]);
    table.add_row(row);
  }
  lesson.table(table, "hemicube_aliasing");
}

}  // namespace lesson06
