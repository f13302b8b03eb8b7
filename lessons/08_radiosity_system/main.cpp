// Lesson 08 -- the radiosity system. A small Cornell box: the matrix K = I - R F,
// its direct solution, and the Neumann series B = E + RFE + (RF)^2 E + ... pictured
// bounce by bounce, with the energy each bounce adds.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/radiosity/display.hpp"
#include "gi/radiosity/radiosity_scenes.hpp"
#include "gi/radiosity/solvers.hpp"
#include "gi/radiosity/vertex_colours.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/table.hpp"

namespace {

double mean(const gi::Color& c) { return (c.x + c.y + c.z) / 3; }

// (RF) x: what one more bounce makes of the radiosity x.
std::vector<gi::Color> bounce(const gi::RadiositySystem& s, const std::vector<gi::Color>& x) {
  std::vector<gi::Color> y(s.size(), gi::Color(0.0));
  for (int i = 0; i < s.size(); ++i) {
    gi::Color gathered(0.0);
    for (int j = 0; j < s.size(); ++j) gathered += s.F(i, j) * x[j];
    y[i] = s.rho[i] * gathered;
  }
  return y;
}

// K = I - R F (green channel) as a heat map: log10 |K_ij|, the diagonal's 1 in red.
gi::Image matrix_picture(const gi::RadiositySystem& s) {
  std::vector<double> logs(static_cast<std::size_t>(s.size()) * s.size());
  for (int i = 0; i < s.size(); ++i)
    for (int j = 0; j < s.size(); ++j) {
      const double k = (i == j) - s.rho[i].y * s.F(i, j);
      logs[static_cast<std::size_t>(i) * s.size() + j] = k != 0 ? std::log10(std::abs(k)) : -8;
    }
  return gi::false_colour(logs, s.size(), s.size(), -5, 0);
}

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("08_radiosity_system", [&] {
    gi::CommonOptions common;
    int elements = 400, resolution = 100, bounces = 4;
    gi::DisplaySettings display;
    display.width = 256;
    display.height = 256;
    double exposure = 1.5;
    gi::Options options("08_radiosity_system", "The radiosity system (I - RF) B = E of a small Cornell box: the "
                                               "matrix, its direct solution, and the Neumann series bounce by bounce.");
    gi::add_common_options(options, common, "08_radiosity_system");
    options.add("--width", display.width, "image width in pixels", 16, 4096)
        .add("--height", display.height, "image height in pixels", 16, 4096)
        .add("--elements", elements, "about how many elements to mesh the Cornell box into", 20, 3000)
        .add("--resolution", resolution, "hemicube resolution of the form factors (even)", 10, 1000)
        .add("--bounces", bounces, "terms of the Neumann series to picture", 1, 20)
        .add("--exposure", exposure, "multiplies the radiance before display", 0.01, 100.0);
    if (!options.parse(argc, argv)) return 0;
    if (resolution % 2) throw gi::OptionError("the hemicube resolution must be even");
    display.threads = common.threads;
    display.seed = common.seed;
    display.white = 1 / exposure;  // anti-aliased edges on the light (display.hpp)
    const std::string& out = common.out;

    const gi::RadiosityScene scene = gi::cornell_box();
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const gi::FormFactorScene receivers(gi::element_shapes(mesh));
    gi::FormFactorSettings hemicube;
    hemicube.hemicube_resolution = resolution;
    const gi::Timer ff_timer;
    const gi::RadiositySystem system = gi::make_system(mesh, gi::form_factor_matrix(receivers, hemicube, common.threads));
    const double ff_ms = ff_timer.milliseconds();
    const gi::Timer direct_timer;
    const gi::SolverResult direct = gi::solve_direct(system);
    const double direct_ms = direct_timer.milliseconds();
    gi::write_png(matrix_picture(system), out + "/matrix_K.png");
    std::cout << "Cornell box, " << system.size() << " elements: form factors (hemicube " << resolution << ") "
              << gi::format_number(ff_ms, 0, gi::Format::Fixed) << " ms; K = I - RF solved by Gaussian elimination in "
              << gi::format_number(direct_ms, 0, gi::Format::Fixed) << " ms (3 channels, O(n^3))\n\n";

    // The Neumann series, term by term, and the picture after each.
    gi::Table table("Neumann series B = E + RFE + (RF)^2 E + ...: power per term (mean of R, G, B)",
                    {{"term"}, {"light"}, {"power", 4, gi::Format::Scientific}, {"share of B %", 2},
                     {"still missing %", 2}});
    const double total = mean(gi::power(system.area, direct.B));
    std::vector<gi::Color> term = system.emission, partial(system.size(), gi::Color(0.0));
    std::vector<gi::Image> strip;
    for (int k = 0; k <= bounces + 1; ++k) {
      for (int i = 0; i < system.size(); ++i) partial[i] += term[i];
      const std::string label = k == 0 ? "emission" : k == 1 ? "direct light" : std::to_string(k - 1) + " bounce" + (k > 2 ? "s" : "");
      const double p = mean(gi::power(system.area, term));
      table.add_row({k, label, p, 100 * p / total, 100 * (1 - mean(gi::power(system.area, partial)) / total)});
      strip.push_back(gi::render_radiosity(receivers, mesh, partial, scene.camera, display));
      gi::write_png(strip.back(), out + "/neumann_" + std::to_string(k) + ".png", exposure);
      term = bounce(system, term);
    }
    strip.push_back(gi::render_radiosity(receivers, mesh, direct.B, scene.camera, display));
    gi::write_png(strip.back(), out + "/solution.png", exposure);
    gi::write_png(gi::side_by_side(strip), out + "/neumann_series.png", exposure);
    table.print();
    table.write_csv(out + "/neumann.csv");

    display.shading = gi::Shading::Flat;
    gi::write_png(gi::render_radiosity(receivers, mesh, direct.B, scene.camera, display), out + "/solution_flat.png",
                  exposure);
    gi::write_ply(mesh, gi::vertex_radiosity(mesh, direct.B), exposure, out + "/cornell.ply");
    std::cout << "\nimages: " << out << "/ (neumann_series.png: emission, direct, bounces..., solution; matrix_K.png; "
              << "cornell.ply for MeshLab or Blender)\n";
    return 0;
  });
}
