// Lesson 11 -- progressive refinement: shoot from the patch with the most unshot
// power, one hemicube per shot, no matrix stored, a picture after every step; with and
// without the ambient term. The lecture's figure: after 1, 2, 24 and 100 steps.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gi/core/norms.hpp"
#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/mesh/radiosity_scene_file.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/viewer/demos.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

// RMS difference to the reference over the elements that do not emit, relative to
// their RMS: the light's own elements, right from the start and 10x brighter than
// anything else, would otherwise hide the error everywhere else. Both are scaled by
// the reference's largest value first (core/norms.hpp): under a light of 1e-300 the
// squares would be 0.
double error(const std::vector<gi::Color>& B, const std::vector<gi::Color>& reference,
             const std::vector<gi::Color>& emission) {
  const double s = gi::power_of_two_scale(gi::largest_channel(reference));
  double d2 = 0, b2 = 0;
  for (std::size_t i = 0; i < B.size(); ++i)
    if (gi::max_component(emission[i]) == 0)
      d2 += gi::length_squared(s * (B[i] - reference[i])), b2 += gi::length_squared(s * reference[i]);
  return std::sqrt(d2 / b2);
}

// The shots after which the table gets a row, and those that also get pictures
// (the lecture's figure).
const std::vector<int> table_shots = {1, 2, 4, 8, 16, 24, 50, 100, 200, 400, 800};
const std::vector<int> picture_shots = {1, 2, 24, 100};

bool contains(const std::vector<int>& list, int value) { return std::find(list.begin(), list.end(), value) != list.end(); }

struct Box {
  gi::RadiosityScene scene;
  gi::Mesh mesh;
  gi::FormFactorScene receivers;
  gi::RadiositySystem system;  // shooting needs no matrix: F stays empty
  Box(const gi::RadiosityScene& s, double patch_size, int elements_per_side)
      : scene(s),
        mesh(gi::make_mesh(scene.surfaces, {patch_size, elements_per_side})),
        receivers(gi::element_shapes(mesh)),
        system(gi::make_system(mesh, {})) {}
};

// The rows `remembered` keeps, one double per element for every patch shot: counted
// before any work (element_count, the mesher's own arithmetic), so that --patches 5000
// --elements-per-side 8 (13 GB of rows) is refused at once rather than run out of memory.
void check_kept_rows(const gi::RadiosityScene& scene, int patches, int per_side) {
  const gi::MeshSettings mesh{gi::patch_size_for(scene.surfaces, patches * per_side * per_side, per_side), per_side};
  const double elements = gi::element_count(scene.surfaces, mesh), rows = elements / (per_side * per_side);
  const double gigabytes = rows * elements * sizeof(double) / 1e9, most = 3.2;  // a 20 000-element matrix's
  if (gigabytes > most)
    throw gi::OptionError("--patches " + std::to_string(patches) + " with --elements-per-side " +
                          std::to_string(per_side) + " makes " + gi::format_number(rows, 0, gi::Format::Fixed) +
                          " patches of " + gi::format_number(elements, 0, gi::Format::Fixed) +
                          " elements: the rows kept for shooting would take " +
                          gi::format_number(gigabytes, 1, gi::Format::Fixed) + " GB, more than " +
                          gi::format_number(most, 1, gi::Format::Fixed) + "; use fewer patches or elements per side");
}

// Patch p's row, computed the first time a shot asks for it and kept: a row depends
// only on the geometry, not on the light being shot, and the converged answer and the
// viewer's replay shoot the same patches again and again. The watched run below does
// not use it, so that its time column is the cost of shooting.
gi::ShooterRow remembered(gi::ShooterRow row) {
  auto rows = std::make_shared<std::map<int, std::vector<double>>>();
  return [row = std::move(row), rows](int p) {
    auto kept = rows->find(p);
    if (kept == rows->end()) kept = rows->emplace(p, row(p)).first;
    return kept->second;
  };
}

// 1. The shots, watched: a table row at each of table_shots, pictures with and
// without the ambient term at each of picture_shots, error against the converged answer.
void watch_the_shots(const Box& box, const gi::ShooterRow& row, const gi::ShooterRow& kept_row,
                     const gi::DisplaySettings& display, double exposure, gi::Lesson& lesson) {
  gi::SolverOptions converge;
  converge.tolerance = 1e-4;
  converge.max_steps = 1'000'000;
  const gi::SolverResult reference = gi::solve_progressive(box.system, box.mesh, kept_row, converge);
  // Without a converged answer the error column would measure against garbage.
  if (reference.status != gi::SolveStatus::Converged)
    throw std::runtime_error("no converged answer to measure the error against: shooting to 1e-4 unshot energy " +
                             gi::stop_reason(reference, "shot"));

  gi::Table table("Progressive refinement, " + std::to_string(box.mesh.patches.size()) + " patches, " +
                      std::to_string(box.mesh.elements.size()) + " elements (error against the converged answer)",
                  {{"shots"}, {"unshot energy %", 3}, {"error", 2, gi::Format::Scientific},
                   {"error with ambient", 2, gi::Format::Scientific}, {"ms", 0}});
  std::vector<gi::Image> plain, ambient;
  gi::Series unshot_curve{"unshot energy", {}, {}}, error_curve{"error", {}, {}}, ambient_curve{"error with ambient", {}, {}};
  const gi::View view{box.scene.camera, display.width, display.height, gi::describe_pixel_samples(display)};
  const auto draw = [&](const std::vector<gi::Color>& B, const std::string& stem, const std::string& caption) {
    const gi::RadiosityPicture picture = gi::render_radiosity_picture(box.receivers, box.mesh, B, box.scene.camera, display,
                                                                      lesson.seed(), lesson.threads());
    lesson.picture(picture.radiance, stem, caption, view, exposure, &picture.shown);
    return picture.shown;
  };
  gi::SolverOptions watched;
  watched.tolerance = 0;
  watched.max_steps = table_shots.back();
  watched.observer = [&](const gi::SolverStep& step, const std::vector<gi::Color>& B, const std::vector<gi::Color>& unshot) {
    if (!contains(table_shots, step.step)) return;
    const gi::RadiositySystem& s = box.system;
    const std::vector<gi::Color> shown = gi::with_ambient(s.area, s.rho, B, unshot);
    const double e = error(B, reference.B, s.emission), e_ambient = error(shown, reference.B, s.emission);
    table.add_row({step.step, 100 * step.unshot, e, e_ambient, 1e3 * step.seconds});
    unshot_curve.x.push_back(step.step), unshot_curve.y.push_back(step.unshot);
    error_curve.x.push_back(step.step), error_curve.y.push_back(e);
    ambient_curve.x.push_back(step.step), ambient_curve.y.push_back(e_ambient);
    if (!contains(picture_shots, step.step)) return;
    const std::string shots = std::to_string(step.step);
    plain.push_back(draw(B, "shots_" + shots, "after " + shots + " shots"));
    ambient.push_back(draw(shown, "shots_" + shots + "_ambient", "after " + shots + " shots, with the ambient term"));
  };
  const gi::SolverResult run = gi::solve_progressive(box.system, box.mesh, row, watched);
  lesson.table(table, "progressive");
  if (run.status != gi::SolveStatus::StoppedAtLimit) lesson.say("shooting " + gi::stop_reason(run, "shot"));
  lesson.diagram(gi::side_by_side(plain), "snapshots", "after 1, 2, 24 and 100 shots", exposure);
  lesson.diagram(gi::side_by_side(ambient), "snapshots_ambient", "after 1, 2, 24 and 100 shots, with the ambient term",
                 exposure);
  lesson.chart({"Progressive refinement: unshot energy and error against shots", "shots", "fraction", true, true,
                {unshot_curve, error_curve, ambient_curve}},
               "progress");
}

// 2. Speed: shots until 1% of the emitted energy is left unshot, on a fine mesh,
// shooting from patches of 4 x 4 elements (the lecture's two levels), one thread.
void time_to_one_percent(const gi::RadiosityScene& scene, int elements, const gi::FormFactorSettings& hemicube,
                         gi::Lesson& lesson) {
  const Box fine(scene, gi::patch_size_for(scene.surfaces, elements, 4), 4);
  gi::SolverOptions one_percent;
  one_percent.tolerance = 0.01;
  one_percent.max_steps = 1'000'000;
  const gi::Timer timer;
  const gi::SolverResult fast =
      gi::solve_progressive(fine.system, fine.mesh, gi::patch_shooter(fine.receivers, fine.mesh, hemicube), one_percent);
  if (fast.status != gi::SolveStatus::Converged)
    throw std::runtime_error("the timing to 1% unshot energy: shooting " + gi::stop_reason(fast, "shot"));
  lesson.say("\n" + std::to_string(fine.mesh.elements.size()) + " elements in " +
             std::to_string(fine.mesh.patches.size()) + " patches: " + std::to_string(fast.history.size()) +
             " shots to 1% unshot energy in " + gi::format_number(timer.seconds(), 2, gi::Format::Fixed) +
             " s (hemicube " + std::to_string(hemicube.hemicube_resolution) + ", one thread)");
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("11_progressive", "Progressive refinement on the Cornell box: snapshots after 1, 2, 24 and 100 "
                                      "shots with and without the ambient term; unshot energy and error per step.");
  int patches = 400, elements_per_side = 2, speed_elements = 3000;
  const int most_patches = 5000;
  gi::FormFactorSettings hemicube;
  gi::DisplaySettings display;
  display.width = 200;
  display.height = 200;
  double exposure = 1.5;
  std::string scene_name = "cornell";
  gi::SceneChanges changes;
  gi::RadiosityScene scene;
  lesson.add_image_size(display.width, display.height);
  lesson.add_scene(scene_name, gi::radiosity_scene_names(), [&](const std::string& choice, auto& warnings) {
    scene = gi::load_radiosity_scene(choice, changes, most_patches, warnings, lesson.scene_file_rules());
  });
  lesson.add_scene_changes(changes);
  lesson.options()
      .add("--patches", patches, "about how many patches to cut the scene into", 20, most_patches)
      .add("--elements-per-side", elements_per_side, "each patch is n x n elements", 1, 8)
      .add("--resolution", hemicube.hemicube_resolution, "hemicube resolution", 10, 1000, gi::even)
      .add("--speed-elements", speed_elements, "elements for the timing to 1% unshot energy (docs/11 quotes 10 000)", 100, 100000)
      .add("--exposure", exposure, "multiplies the radiance before display", 0.01, 100.0);
  lesson.add_check([&] { check_kept_rows(scene, patches, elements_per_side); });
  return lesson.run(argc, argv, [&] {
    display.white = 1 / exposure;  // anti-aliased edges on the light (display.hpp)
    const Box box(scene, gi::patch_size_for(scene.surfaces, patches * elements_per_side * elements_per_side, elements_per_side),
                  elements_per_side);
    const gi::ShooterRow row = gi::patch_shooter(box.receivers, box.mesh, hemicube), kept_row = remembered(row);
    watch_the_shots(box, row, kept_row, display, exposure, lesson);
    lesson.viewer("progressive refinement replayed shot by shot", [&](const std::filesystem::path& file) {
      gi::write_viewer_data(gi::progressive_replay(lesson.name(), box.scene, box.mesh, box.system, kept_row,
                                                   table_shots.back(), exposure),
                            file);
    });
    time_to_one_percent(scene, speed_elements, hemicube, lesson);
    lesson.say("\nimages: " + lesson.out().string() + "/ (snapshots.png and snapshots_ambient.png: after 1, 2, 24, " +
               "100 shots)");
  });
}
