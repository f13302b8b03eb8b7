// Lesson 08 -- the radiosity system. A small Cornell box: the matrix K = I - R F,
// its direct solution, and the Neumann series B = E + RFE + (RF)^2 E + ... pictured
// bounce by bounce, with the energy each bounce adds.
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/mesh/radiosity_scene_file.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"
#include "gi/viewer/demos.hpp"
#include "gi/report/lesson.hpp"
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
  gi::Lesson lesson("08_radiosity_system", "The radiosity system (I - RF) B = E of a small Cornell box: the "
                                           "matrix, its direct solution, and the Neumann series bounce by bounce.");
  int elements = 400, resolution = 100, bounces = 4;
  const int most_elements = 3000;  // the direct solution is O(n^3)
  gi::DisplaySettings display;
  display.width = 256;
  display.height = 256;
  double exposure = 1.5;
  std::string scene_name = "cornell";
  gi::SceneChanges changes;
  gi::RadiosityScene scene;
  lesson.add_image_size(display.width, display.height);
  lesson.add_scene(scene_name, gi::radiosity_scene_names(), [&](const std::string& choice, auto& warnings) {
    scene = gi::load_radiosity_scene(choice, changes, most_elements, warnings, lesson.scene_file_rules());
  });
  lesson.add_scene_changes(changes);
  lesson.options()
      .add("--elements", elements, "about how many elements to mesh the scene into", 20, most_elements)
      .add("--resolution", resolution, "hemicube resolution of the form factors", 10, 1000, gi::even)
      .add("--bounces", bounces, "terms of the Neumann series to picture", 1, 20)
      .add("--exposure", exposure, "multiplies the radiance before display", 0.01, 100.0);
  // The strip of pictures (emission, direct, the bounces, the solution) is one image.
  lesson.add_check([&] {
    const int pictures = bounces + 3;
    if (pictures * (display.width + 4) - 4 > gi::max_image_side)
      throw gi::OptionError("--width " + std::to_string(display.width) + " makes the strip of " +
                            std::to_string(pictures) + " pictures wider than " + std::to_string(gi::max_image_side) +
                            " pixels; use at most --width " + std::to_string((gi::max_image_side + 4) / pictures - 4) +
                            " with --bounces " + std::to_string(bounces));
  });
  return lesson.run(argc, argv, [&] {
    display.white = 1 / exposure;  // anti-aliased edges on the light (display.hpp)

    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const gi::FormFactorScene receivers(gi::element_shapes(mesh));
    gi::FormFactorSettings hemicube;
    hemicube.hemicube_resolution = resolution;
    const gi::Timer ff_timer;
    const gi::RadiositySystem system = gi::make_system(mesh, gi::form_factor_matrix(receivers, hemicube, lesson.threads()));
    const double ff_ms = ff_timer.milliseconds();
    const gi::Timer direct_timer;
    const gi::SolverResult direct = gi::solve_direct(system);
    const double direct_ms = direct_timer.milliseconds();
    if (direct.status != gi::SolveStatus::Converged)
      throw std::runtime_error("the direct solution failed: " + gi::stop_reason(direct, "step"));
    lesson.diagram(matrix_picture(system), "matrix_K", "log10 |K_ij| of K = I - RF in false colour, black below 1e-5 to red at 1 (the diagonal)",
                   gi::ColourScale{1e-5, 1, "|K_ij|", true});
    const std::string title = scene_name == "cornell" ? "Cornell box" : "Scene " + scene.name;
    lesson.say(title + ", " + std::to_string(system.size()) + " elements: form factors (hemicube " +
               std::to_string(resolution) + ") " + gi::format_number(ff_ms, 0, gi::Format::Fixed) +
               " ms; K = I - RF solved by Gaussian elimination in " + gi::format_number(direct_ms, 0, gi::Format::Fixed) +
               " ms (3 channels, O(n^3))\n");

    // The Neumann series, term by term, and the picture after each.
    gi::Table table("Neumann series B = E + RFE + (RF)^2 E + ...: power per term (mean of R, G, B)",
                    {{"term"}, {"light"}, {"power", 4, gi::Format::Scientific}, {"share of B %", 2},
                     {"still missing %", 2}});
    const double total = mean(gi::power(system.area, direct.B));
    const gi::View view{scene.camera, display.width, display.height, gi::describe_pixel_samples(display)};
    std::vector<gi::Color> term = system.emission, partial(system.size(), gi::Color(0.0));
    std::vector<gi::Image> strip;
    for (int k = 0; k <= bounces + 1; ++k) {
      for (int i = 0; i < system.size(); ++i) partial[i] += term[i];
      const std::string label = k == 0 ? "emission" : k == 1 ? "direct light" : std::to_string(k - 1) + " bounce" + (k > 2 ? "s" : "");
      const double p = mean(gi::power(system.area, term));
      table.add_row({k, label, p, 100 * p / total, 100 * (1 - mean(gi::power(system.area, partial)) / total)});
      const gi::RadiosityPicture picture = gi::render_radiosity_picture(receivers, mesh, partial, scene.camera, display,
                                                                        lesson.seed(), lesson.threads());
      strip.push_back(picture.shown);
      lesson.picture(picture.radiance, "neumann_" + std::to_string(k), "the Neumann series up to " + label, view,
                     exposure, &picture.shown);
      term = bounce(system, term);
    }
    const gi::RadiosityPicture solution =
        gi::render_radiosity_picture(receivers, mesh, direct.B, scene.camera, display, lesson.seed(), lesson.threads());
    strip.push_back(solution.shown);
    lesson.picture(solution.radiance, "solution", "the direct solution, smooth shading", view, exposure, &solution.shown);
    lesson.diagram(gi::side_by_side(strip), "neumann_series", "emission, direct light, the bounces and the solution",
                   exposure);
    lesson.table(table, "neumann");

    display.shading = gi::Shading::Flat;
    const gi::RadiosityPicture flat =
        gi::render_radiosity_picture(receivers, mesh, direct.B, scene.camera, display, lesson.seed(), lesson.threads());
    lesson.picture(flat.radiance, "solution_flat", "the direct solution, flat shading", view, exposure, &flat.shown);
    lesson.file(gi::file_stem(scene.name) + ".ply", gi::OutputKind::Mesh, "the mesh with vertex colours sRGB(exposure B / pi)",
                [&](const std::filesystem::path& file) {
                  gi::write_ply(mesh, gi::vertex_radiosity(mesh, direct.B), exposure, file);
                });
    lesson.viewer("the Neumann series term by term; relighting with two more lamps", [&](const std::filesystem::path& file) {
      gi::write_viewer_data(gi::neumann_and_relighting(lesson.name(), scene, mesh, system, bounces + 1, exposure,
                                                       {"short block top", "tall block top"}),
                            file);
    });
    lesson.say("\nimages: " + lesson.out().string() + "/ (neumann_series.png: emission, direct, bounces..., " +
               "solution; matrix_K.png; " + gi::file_stem(scene.name) + ".ply for MeshLab or Blender)");
  });
}
