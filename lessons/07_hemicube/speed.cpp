// Lesson 07, step 4: one row by the hemicube and by rays, time against error (steps.hpp).
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "steps.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/report/table.hpp"

namespace lesson07 {
namespace {

// 4000000 as "4M", 40000 as "40000".
std::string rays_text(int rays) {
  return rays % 1'000'000 == 0 ? std::to_string(rays / 1'000'000) + "M" : std::to_string(rays);
}

// The L1 distance between two rows, relative to the reference's sum.
double row_error(const std::vector<double>& row, const std::vector<double>& reference) {
  double difference = 0, total = 0;
  for (std::size_t j = 0; j < row.size(); ++j) difference += std::abs(row[j] - reference[j]), total += reference[j];
  return difference / total;
}

}  // namespace

// One row of a finely meshed box: the hemicube at resolution 100 against rays cast
// from the element (Monte Carlo: a tenth, a third and all of `most_rays`), both
// measured against a row of 40/3 as many rays (4 million for the default 300 000).
void speed_table(const gi::Mesh& mesh, int element, int most_rays, gi::Lesson& lesson) {
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const gi::Polygon& from = scene.polygons()[element];
  gi::FormFactorSettings reference_settings;
  reference_settings.method = gi::FormFactorMethod::MonteCarlo;
  reference_settings.rays = most_rays / 3 * 40;
  reference_settings.seed = lesson.seed();
  const std::vector<double> reference = gi::form_factor_row(scene, from, 999, reference_settings);
  gi::Table table("One row against " + std::to_string(scene.polygons().size()) +
                      " elements, one thread: time and L1 error against " + rays_text(reference_settings.rays) +
                      " rays (median of 7 rows)",
                  {{"method"}, {"samples"}, {"ms per row", 2}, {"rows per second", 0}, {"row error", 2, gi::Format::Scientific}});
  const auto measure = [&](const std::string& label, long long samples, const gi::FormFactorSettings& s) {
    std::vector<double> times;
    std::vector<double> row;
    for (int run = 0; run < 7; ++run) {
      const gi::Timer timer;
      row = gi::form_factor_row(scene, from, run, s);
      times.push_back(timer.milliseconds());
    }
    table.add_row({label, samples, gi::median(times), 1e3 / gi::median(times), row_error(row, reference)});
  };
  gi::FormFactorSettings hemicube;
  measure("hemicube, resolution 100", 3 * 100 * 100, hemicube);
  for (int rays : {most_rays / 10, most_rays / 3, most_rays}) {
    gi::FormFactorSettings mc = reference_settings;
    mc.rays = rays;
    measure("rays (Monte Carlo)", rays, mc);
  }
  std::cout << '\n';
  lesson.table(table, "speed");
}

}  // namespace lesson07
