// Lesson 06 -- form factors: the differential formula, the analytic contour integral,
// Monte Carlo (Nusselt's analogue by rays) and the hemicube, on the configurations
// whose exact answers the heat-transfer literature gives; where each fails (near
// field, far field, shared edges, thin strips, receivers smaller than a hemicube
// cell, occlusion, aliasing, noise) and what its accuracy costs.
// Step 1 is here; the studies of where each fails and what accuracy costs are in
// failures.cpp and error_against_time.cpp, what they share in configurations.cpp.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "configurations.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "studies.hpp"

namespace {

using lesson06::Case;
using lesson06::facing_squares;
using lesson06::FormFactorMethod;
using lesson06::rectangle;
using lesson06::with;

// 1. Every method on every validation case: the configurations whose exact answers the
//    heat-transfer literature gives, and two squares with a blocker between them.
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
    for (FormFactorMethod m : lesson06::methods) {
      const auto [value, us] = lesson06::evaluate(scene, with(m, base));
      // Monte Carlo against Monte Carlo with more rays measures only its convergence.
      const bool itself = m == FormFactorMethod::MonteCarlo && c.source.starts_with("Monte Carlo");
      table.add_row({c.name, gi::name(m), value, c.exact, std::abs(value - c.exact) / c.exact,
                     own_estimate(scene, with(m, base)), us, itself ? c.source + " (convergence study)" : c.source});
    }
  }
  lesson.table(table, "validation");
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
    lesson06::geometry_figure(lesson);
    double reference_ms = 0;
    const std::vector<Case> list = cases(reference_rays, reference_ms);
    every_method_every_case(list, base, lesson);
    lesson.say("(the occluded case's reference took " + gi::format_number(reference_ms, 0, gi::Format::Fixed) +
               " ms)\n");
    lesson06::where_each_method_fails(base, lesson);
    std::cout << '\n';
    lesson06::near_field(base, lesson);
    std::cout << '\n';
    lesson06::hemicube_aliasing(lesson);
    std::cout << '\n';
    lesson06::error_against_time(sweep_rays, lesson);
    std::cout << '\n';
    lesson06::one_row(base, lesson);
    lesson.say("\ntables, chart and picture: " + lesson.out().string() + "/");
  });
}
