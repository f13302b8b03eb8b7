// Lesson 06 -- form factors: the differential formula, the analytic contour integral,
// Monte Carlo (Nusselt's analogue by rays) and the hemicube, on the configurations
// whose exact answers the heat-transfer literature gives; where each fails (near
// field, far field, shared edges, thin strips, receivers smaller than a hemicube
// cell, occlusion, aliasing, noise) and what its accuracy costs.
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/item_buffer.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

using gi::FormFactorMethod;
using gi::vec3;

// A w x h rectangle centred at `centre`, spanned by unit vectors u and v, facing u x v.
gi::Polygon rectangle(vec3 centre, vec3 u, vec3 v, double w, double h) {
  const vec3 c0 = centre - 0.5 * w * u - 0.5 * h * v;
  return gi::make_polygon({c0, c0 + w * u, c0 + w * u + h * v, c0 + h * v});
}

// Two unit squares facing each other at distance d (sender first, facing up).
std::vector<gi::Polygon> facing_squares(double d) {
  return {rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1), rectangle({0, d, 0}, {1, 0, 0}, {0, 0, 1}, 1, 1)};
}

struct Case {
  std::string name;
  std::vector<gi::Polygon> polygons;  // F from polygons[0] to polygons[1]
  double exact;
  std::string source;  // where the exact value comes from
};

std::vector<Case> cases(int reference_rays, double& occluded_reference_ms) {
  std::vector<Case> list;
  list.push_back({"parallel squares, d = 1", facing_squares(1), gi::ff_parallel_rectangles(1, 1, 1), "closed form"});
  list.push_back({"parallel squares, d = 0.2", facing_squares(0.2), gi::ff_parallel_rectangles(1, 1, 0.2), "closed form"});
  list.push_back({"parallel squares, d = 5", facing_squares(5), gi::ff_parallel_rectangles(1, 1, 5), "closed form"});
  list.push_back({"perpendicular squares",
                  {rectangle({0.5, 0, 0.5}, {0, 0, 1}, {1, 0, 0}, 1, 1), rectangle({0.5, 0.5, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1)},
                  gi::ff_perpendicular_rectangles(1, 1, 1), "closed form"});
  // A sender of 1e-7 x 1e-7 is a differential area (to 1e-14); the rectangle's corner is above it.
  list.push_back({"point to rectangle",
                  {rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1e-7, 1e-7),
                   rectangle({0.65, 0.9, 0.3}, {1, 0, 0}, {0, 0, 1}, 1.3, 0.6)},
                  gi::ff_point_to_parallel_rectangle_corner(1.3, 0.6, 0.9), "closed form"});
  // A blocker halfway: no closed form; the reference is Monte Carlo with many rays.
  std::vector<gi::Polygon> blocked = facing_squares(2);
  blocked.push_back(rectangle({0, 0.995, 0}, {1, 0, 0}, {0, 0, 1}, 0.5, 0.5));  // underside, facing down
  blocked.push_back(rectangle({0, 1.005, 0}, {0, 0, 1}, {1, 0, 0}, 0.5, 0.5));  // top, facing up
  gi::FormFactorSettings reference;
  reference.method = FormFactorMethod::MonteCarlo;
  reference.rays = reference_rays;
  const gi::Timer timer;
  const double f = gi::form_factor_row(gi::FormFactorScene(blocked), blocked[0], 0, reference)[1];
  occluded_reference_ms = timer.milliseconds();
  list.push_back({"occluded squares, d = 2", blocked, f, "Monte Carlo, " + std::to_string(reference_rays) + " rays"});
  return list;
}

// F from polygons[0] to polygons[1] by `settings`, and its time in microseconds
// (median of at least three runs, and of enough runs to fill 20 ms).
// `row` picks the random stream of a Monte Carlo estimate; `runs` is the least
// number of timed runs.
std::pair<double, double> evaluate(const gi::FormFactorScene& scene, const gi::FormFactorSettings& settings,
                                   int row = 0, std::size_t runs = 3) {
  std::vector<double> times;
  double value = 0, total = 0;
  while (times.size() < runs || (total < 0.02 && times.size() < 1000)) {
    const gi::Timer timer;
    value = gi::form_factor_row(scene, scene.polygons()[0], row, settings)[1];
    times.push_back(timer.seconds());
    total += times.back();
  }
  return {value, 1e6 * gi::median(times)};
}

gi::FormFactorSettings with(FormFactorMethod method, const gi::FormFactorSettings& base) {
  gi::FormFactorSettings s = base;
  s.method = method;
  return s;
}

const FormFactorMethod methods[] = {FormFactorMethod::Differential, FormFactorMethod::Analytic,
                                    FormFactorMethod::MonteCarlo, FormFactorMethod::Hemicube};

// The method's own error estimate for F from polygons[0] to polygons[1], relative:
// the analytic method's bound, Monte Carlo's standard error; "-" for the point methods.
gi::Cell own_estimate(const gi::FormFactorScene& scene, const gi::FormFactorSettings& settings) {
  const gi::FormFactorRow row = gi::form_factor_row_with_diagnostics(scene, scene.polygons()[0], 0, settings);
  if (row.error.empty() || row.F[1] == 0) return "-";
  return row.error[1] / row.F[1];
}

void every_method_every_case(const std::vector<Case>& list, const gi::FormFactorSettings& base, gi::Lesson& lesson) {
  gi::Table table("Every method on every validation case (analytic tolerance " +
                      gi::format_number(base.tolerance, 0, gi::Format::Scientific) + ", " + std::to_string(base.rays) +
                      " rays, hemicube " + std::to_string(base.hemicube_resolution) + ")",
                  {{"case"}, {"method"}, {"F", 5}, {"exact", 5}, {"rel. error", 2, gi::Format::Scientific},
                   {"own estimate", 1, gi::Format::Scientific}, {"us", 1}, {"exact from"}});
  for (const Case& c : list) {
    const gi::FormFactorScene scene(c.polygons);
    for (FormFactorMethod m : methods) {
      const auto [value, us] = evaluate(scene, with(m, base));
      // Monte Carlo against Monte Carlo with more rays measures only its convergence.
      const bool itself = m == FormFactorMethod::MonteCarlo && c.source.starts_with("Monte Carlo");
      table.add_row({c.name, gi::name(m), value, c.exact, std::abs(value - c.exact) / c.exact,
                     own_estimate(scene, with(m, base)), us, itself ? c.source + " (convergence study)" : c.source});
    }
  }
  lesson.table(table, "validation");
}

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

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("06_form_factors", "Form factors: differential, analytic, Monte Carlo and hemicube against "
                                       "closed forms; near field, occlusion, aliasing, noise; error against time.",
                    {.threads = false});
  gi::FormFactorSettings base;
  base.rays = 10000;
  base.quadrature_order = 4;
  int sweep_rays = 1'000'000, reference_rays = 4'000'000;
  lesson.options()
      .add("--rays", base.rays, "Monte Carlo rays per form factor", 1, 10'000'000)
      .add("--order", base.quadrature_order, "analytic: the first order of Gauss points over the sender", 1, 16)
      .add("--tolerance", base.tolerance, "analytic: relative error of each form factor", 1e-14, 0.1)
      .add("--resolution", base.hemicube_resolution, "hemicube cells across the top face", 2, 2000, gi::even)
      .add("--sweep-rays", sweep_rays, "largest ray count in the error-against-time sweep", 100, 100'000'000)
      .add("--reference-rays", reference_rays, "Monte Carlo rays of the occluded case's reference", 1000,
           100'000'000);
  return lesson.run(argc, argv, [&] {
    base.seed = lesson.seed();
    double reference_ms = 0;
    const std::vector<Case> list = cases(reference_rays, reference_ms);
    every_method_every_case(list, base, lesson);
    lesson.say("(the occluded case's reference took " + gi::format_number(reference_ms, 0, gi::Format::Fixed) +
               " ms)\n");
    where_each_method_fails(base, lesson);
    std::cout << '\n';
    near_field(base, lesson);
    std::cout << '\n';
    hemicube_aliasing(lesson);
    std::cout << '\n';
    error_against_time(sweep_rays, lesson);
    lesson.say("\ntables and chart: " + lesson.out().string() + "/");
  });
}
