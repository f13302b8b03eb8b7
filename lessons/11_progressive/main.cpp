// Lesson 11 -- progressive refinement: shoot from the patch with the most unshot
// power, one hemicube per shot, no matrix stored, a picture after every step; with and
// without the ambient term. The lecture's figure: after 1, 2, 24 and 100 steps.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/radiosity/display.hpp"
#include "gi/radiosity/progressive.hpp"
#include "gi/radiosity/radiosity_scenes.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/table.hpp"

namespace {

// RMS difference to the reference over the elements that do not emit, relative to
// their RMS: the light's own elements, right from the start and 10x brighter than
// anything else, would otherwise hide the error everywhere else.
double error(const std::vector<gi::Color>& B, const std::vector<gi::Color>& reference,
             const std::vector<gi::Color>& emission) {
  double d2 = 0, b2 = 0;
  for (std::size_t i = 0; i < B.size(); ++i)
    if (gi::max_component(emission[i]) == 0)
      d2 += gi::length_squared(B[i] - reference[i]), b2 += gi::length_squared(reference[i]);
  return std::sqrt(d2 / b2);
}

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("11_progressive", [&] {
    gi::CommonOptions common;
    int patches = 400, elements_per_side = 2, resolution = 100, speed_elements = 10000;
    gi::DisplaySettings display;
    display.width = 200;
    display.height = 200;
    double exposure = 1.5;
    gi::Options options("11_progressive", "Progressive refinement on the Cornell box: snapshots after 1, 2, 24 and 100 "
                                          "shots with and without the ambient term; unshot energy and error per step.");
    gi::add_common_options(options, common, "11_progressive");
    options.add("--width", display.width, "image width in pixels", 16, 4096)
        .add("--height", display.height, "image height in pixels", 16, 4096)
        .add("--patches", patches, "about how many patches to cut the box into", 20, 5000)
        .add("--elements-per-side", elements_per_side, "each patch is n x n elements", 1, 8)
        .add("--resolution", resolution, "hemicube resolution (even)", 10, 1000)
        .add("--speed-elements", speed_elements, "elements for the timing to 1% unshot energy", 100, 100000)
        .add("--exposure", exposure, "multiplies the radiance before display", 0.01, 100.0);
    if (!options.parse(argc, argv)) return 0;
    if (resolution % 2) throw gi::OptionError("the hemicube resolution must be even");
    display.threads = common.threads;
    display.seed = common.seed;
    display.white = 1 / exposure;  // anti-aliased edges on the light (display.hpp)
    const std::string& out = common.out;

    const gi::RadiosityScene scene = gi::cornell_box();
    const double patch_size = gi::patch_size_for(scene.surfaces, patches * elements_per_side * elements_per_side,
                                                 elements_per_side);
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {patch_size, elements_per_side});
    const gi::FormFactorScene receivers(gi::element_shapes(mesh));
    gi::FormFactorSettings hemicube;
    hemicube.hemicube_resolution = resolution;
    const gi::ShooterRow row = [&](int p) { return gi::form_factor_row(receivers, mesh.patches[p].shape, p, hemicube); };
    const gi::RadiositySystem system = gi::make_system(mesh, {});  // shooting needs no matrix

    // The converged answer, for the error column.
    gi::SolverOptions converge;
    converge.tolerance = 1e-4;
    converge.max_steps = 1'000'000;
    const gi::SolverResult reference = gi::solve_progressive(system, mesh, row, converge);

    // The same shots again, watched: a table row, and at four steps pictures.
    gi::Table table("Progressive refinement, " + std::to_string(mesh.patches.size()) + " patches, " +
                        std::to_string(mesh.elements.size()) + " elements (error against the converged answer)",
                    {{"shots"}, {"unshot energy %", 3}, {"error", 2, gi::Format::Scientific},
                     {"error with ambient", 2, gi::Format::Scientific}, {"ms", 0}});
    std::vector<gi::Image> plain, ambient;
    gi::Series unshot_curve{"unshot energy", {}, {}}, error_curve{"error", {}, {}}, ambient_curve{"error with ambient", {}, {}};
    const std::vector<int> rows = {1, 2, 4, 8, 16, 24, 50, 100, 200, 400, 800};
    gi::SolverOptions watched;
    watched.tolerance = 0;
    watched.max_steps = rows.back();
    watched.observer = [&](const gi::SolverStep& step, const std::vector<gi::Color>& B, const std::vector<gi::Color>& unshot) {
      if (std::find(rows.begin(), rows.end(), step.step) == rows.end()) return;
      const std::vector<gi::Color> shown = gi::with_ambient(system.area, system.rho, B, unshot);
      const double e = error(B, reference.B, system.emission), e_ambient = error(shown, reference.B, system.emission);
      table.add_row({step.step, 100 * step.unshot, e, e_ambient, 1e3 * step.seconds});
      unshot_curve.x.push_back(step.step), unshot_curve.y.push_back(step.unshot);
      error_curve.x.push_back(step.step), error_curve.y.push_back(e);
      ambient_curve.x.push_back(step.step), ambient_curve.y.push_back(e_ambient);
      if (step.step == 1 || step.step == 2 || step.step == 24 || step.step == 100) {
        plain.push_back(gi::render_radiosity(receivers, mesh, B, scene.camera, display));
        ambient.push_back(gi::render_radiosity(receivers, mesh, shown, scene.camera, display));
        const std::string name = out + "/shots_" + std::to_string(step.step);
        gi::write_png(plain.back(), name + ".png", exposure);
        gi::write_png(ambient.back(), name + "_ambient.png", exposure);
      }
    };
    gi::solve_progressive(system, mesh, row, watched);
    table.print();
    table.write_csv(out + "/progressive.csv");
    gi::write_png(gi::side_by_side(plain), out + "/snapshots.png", exposure);
    gi::write_png(gi::side_by_side(ambient), out + "/snapshots_ambient.png", exposure);
    gi::write_svg({"Progressive refinement: unshot energy and error against shots", "shots", "fraction", true, true,
                   {unshot_curve, error_curve, ambient_curve}},
                  out + "/progress.svg");

    // Speed: shots until 1% of the emitted energy is left unshot, on a fine mesh.
    // Shooting from patches of 4 x 4 elements: the lecture's two levels.
    const gi::Mesh fine = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, speed_elements, 4), 4});
    const gi::FormFactorScene fine_receivers(gi::element_shapes(fine));
    const gi::ShooterRow fine_row = [&](int p) {
      return gi::form_factor_row(fine_receivers, fine.patches[p].shape, p, hemicube);
    };
    gi::SolverOptions one_percent;
    one_percent.tolerance = 0.01;
    one_percent.max_steps = 1'000'000;
    const gi::Timer timer;
    const gi::SolverResult fast = gi::solve_progressive(gi::make_system(fine, {}), fine, fine_row, one_percent);
    std::cout << "\n" << fine.elements.size() << " elements in " << fine.patches.size() << " patches: "
              << fast.history.size() << " shots to 1% unshot energy in "
              << gi::format_number(timer.seconds(), 2, gi::Format::Fixed) << " s (hemicube " << resolution
              << ", one thread)\n";
    std::cout << "\nimages: " << out << "/ (snapshots.png and snapshots_ambient.png: after 1, 2, 24, 100 shots)\n";
    return 0;
  });
}
