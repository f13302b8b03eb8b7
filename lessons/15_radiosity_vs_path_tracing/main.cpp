// Lesson 15 -- radiosity measured against path tracing. The Cornell box by every
// radiosity method of the course and by path tracing, all scored against the stored
// converged picture on one chart of error against time; what path tracing needs to match
// each radiosity recipe; crops of where each fails, side by side; and what radiosity
// cannot draw at all (a mirror, a caustic) and path tracing draws slowly.
// The runs every step reads are made in runs.cpp; step 3 is in specular.cpp.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "crops.hpp"
#include "gi/pathtrace/convergence.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "runs.hpp"
#include "specular.hpp"

namespace {

using lesson15::crops;
using lesson15::Run;
using lesson15::Scoring;
using lesson15::Settings;

// 1. Every method, one table and one chart; and what path tracing needs to match each
// radiosity picture, from its own error law e^2 = v / N + r^2 (convergence.hpp).
void chart_and_table(const std::vector<Run>& radiosity, const std::vector<Run>& paths, const gi::Truth& truth,
                     const Scoring& scoring, const Settings& s, gi::Lesson& lesson) {
  std::vector<gi::ErrorAtSamples> by_block, by_pixel;
  for (const Run& run : paths) {
    const double spp = std::pow(2.0, double(by_block.size()));
    by_block.push_back({spp, run.error}), by_pixel.push_back({spp, run.pixel_error});
  }
  const double v = gi::monte_carlo_variance(by_block, scoring.noise);
  const double v_pixel = gi::monte_carlo_variance(by_pixel, scoring.pixel_noise);
  const double seconds_per_spp = paths.back().seconds / by_block.back().spp;
  const std::string size = std::to_string(s.size) + "x" + std::to_string(s.size);
  const auto percent = [](double x) { return gi::format_number(100 * x, 2, gi::Format::Fixed) + "%"; };
  gi::Table table("The Cornell box against the path-traced truth (" + std::to_string(truth.spp) + " spp; its own " +
                      "error " + percent(scoring.noise) + " over " + std::to_string(scoring.blocks.count()) +
                      " interior blocks of " + size + ", " + percent(scoring.pixel_noise) + " over " +
                      std::to_string(scoring.pixels.count()) + " interior pixels); time from scene to picture",
                  {{"method"}, {"elements"}, {"time s", 2}, {"blocks: rel. RMS %", 2}, {"pixels: rel. RMS %", 2},
                   {"path tracing to match, blocks: spp", 1}, {"pixels: spp", 0}, {"blocks s", 2}, {"pixels s", 1}});
  for (const Run& run : radiosity) {
    const std::optional<double> spp = gi::samples_for_error(v, run.error, scoring.noise);
    const std::optional<double> spp_pixel = gi::samples_for_error(v_pixel, run.pixel_error, scoring.pixel_noise);
    const auto cell = [](std::optional<double> x, double scale) { return x ? gi::Cell(*x * scale) : gi::Cell("never"); };
    table.add_row({run.name, run.elements, run.seconds, 100 * run.error, 100 * run.pixel_error, cell(spp, 1),
                   cell(spp_pixel, 1), cell(spp, seconds_per_spp), cell(spp_pixel, seconds_per_spp)});
  }
  for (const Run& run : paths)
    table.add_row({run.name, "-", run.seconds, 100 * run.error, 100 * run.pixel_error, "-", "-", "-", "-"});
  lesson.table(table, "every_method");
  lesson.say("path tracing's error law, fitted to its " + std::to_string(paths.size()) + " pictures: e^2 = v / spp + " +
             "r^2 with v = " + gi::format_number(v, 3, gi::Format::Scientific) + " over blocks and " +
             gi::format_number(v_pixel, 3, gi::Format::Scientific) + " over pixels, r the reference's own error; " +
             gi::format_number(seconds_per_spp, 3, gi::Format::Fixed) + " s per spp here; never: below r");

  std::vector<gi::Series> curves;
  for (const std::vector<Run>* runs : {&radiosity, &paths})
    for (const Run& run : *runs) {
      if (curves.empty() || curves.back().name != run.family)
        curves.push_back({run.family, {}, {}, runs == &paths ? gi::Mark::LinePoints : gi::Mark::Points});
      curves.back().x.push_back(run.seconds), curves.back().y.push_back(100 * run.error);
    }
  // No error below the reference's own can be told apart from it: its line is the floor.
  double lo = 1e300, hi = 0;
  for (const gi::Series& c : curves)
    for (double x : c.x) lo = std::min(lo, x), hi = std::max(hi, x);
  curves.push_back({"the reference's own error", {lo, hi}, {100 * scoring.noise, 100 * scoring.noise}, gi::Mark::Line});
  lesson.chart({"Cornell box " + size + ": every method against the path-traced truth (" + std::to_string(truth.spp) +
                    " spp, its own error " + percent(scoring.noise) + ")",
                "time from scene to picture (s)", "relative RMS error over interior blocks (%)", true, true, curves},
               "error_vs_time");
}

const Run& nearest_in_time(const std::vector<Run>& runs, double seconds) {
  return *std::min_element(runs.begin(), runs.end(), [&](const Run& a, const Run& b) {
    return std::abs(std::log(a.seconds / seconds)) < std::abs(std::log(b.seconds / seconds));
  });
}

// 2. Where each fails, on the box: the coarsest mesh (blocky, leaking, shadows smeared
// over elements) and the best radiosity picture, against path tracing at the best's
// time and the truth.
void where_each_fails(const std::vector<Run>& radiosity, const std::vector<Run>& paths, const gi::Truth& truth,
                      const gi::View& view, gi::Lesson& lesson) {
  const Run& coarse = radiosity.front();
  const Run& best = *std::min_element(radiosity.begin(), radiosity.end(), [](const Run& a, const Run& b) {
    return a.error < b.error;
  });
  const Run& equal_time = nearest_in_time(paths, best.seconds);
  lesson.picture(coarse.picture, "radiosity_coarse", coarse.name + ", " + std::to_string(coarse.elements) + " elements",
                 view, 2);
  lesson.picture(best.picture, "radiosity_best", best.name + ", " + std::to_string(best.elements) + " elements", view, 2);
  lesson.picture(equal_time.picture, "path_traced_equal_time", equal_time.name, view, 2);
  lesson.picture(truth.mean, "truth", "the path-traced truth, " + std::to_string(truth.spp) + " spp", view, 2);
  const std::vector<const gi::Image*> four = {&coarse.picture, &best.picture, &equal_time.picture, &truth.mean};
  const std::string order = "left to right: radiosity " + std::to_string(coarse.elements) + " elements (" +
                            coarse.name + "), radiosity " + std::to_string(best.elements) + " elements (" + best.name +
                            "), " + equal_time.name + " (about the same time), the truth";
  crops(four, 0.42, 0.62, 0.36, "crop_short_block", "the short block's base and the floor beside it; " + order, lesson);
  crops(four, 0.3, 0.0, 0.4, "crop_ceiling", "the ceiling round the light and the top of the walls; " + order, lesson);
  crops(four, 0.14, 0.56, 0.36, "crop_tall_block", "the tall block's base against the red wall and the floor; " + order, lesson);
  lesson.say("crops: " + order);
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("15_radiosity_vs_path_tracing",
                    "The Cornell box by radiosity and by path tracing against the converged truth: error against "
                    "time for every method, where each fails, and what radiosity cannot draw.");
  Settings s;
  s.reference = std::string(GI_SOURCE_DIR) + "/lessons/references/cornell_256x256";
  lesson.options()
      .add("--size", s.size, "picture width and height: 64, 128 or 256 (the stored truth's, averaged down)", 64, 256)
      .add("--max-spp", s.max_spp, "path tracing's last picture: 1, 2, 4, ... samples per pixel up to it", 2, 1 << 16)
      .add("--caustic-spp", s.caustic_spp, "samples per pixel of the mirror-and-glass box's last picture (its "
                                            "first has 1/16 of them, at least 2: a spread needs two)", 32, 1 << 16)
      .add_flag("--full", s.full, "every mesh of the chart, up to 8 100 elements (minutes)")
      .add("--reference", s.reference, "the Cornell box's converged picture (files STEM.txt, STEM.pfm, ...)");
  const gi::RadiosityScene box = gi::cornell_box();
  std::optional<gi::PathScene> scene;
  std::optional<gi::Truth> truth;
  lesson.add_check([&] {  // before any work: a bad size, a missing, damaged or stale truth, are said at once
    if (256 % s.size != 0) throw gi::OptionError("--size must divide 256 (64, 128 or 256), got " + std::to_string(s.size));
    scene.emplace(gi::make_path_scene(gi::make_path_scene_by_name("cornell")));
    truth = gi::stored_truth_at(s.reference, "cornell", 256, s.size, s.size);
    if (s.size == 256 && lesson.seed() >= truth->seed && lesson.seed() < truth->seed + truth->batches)
      throw gi::OptionError("--seed " + std::to_string(lesson.seed()) + " is one of the reference's own seeds: its "
                            "pictures would share samples with the truth");
  });
  return lesson.run(argc, argv, [&] {
    s.threads = lesson.threads();
    s.seed = lesson.seed();
    Scoring scoring{gi::interior_blocks(box.surfaces, box.camera, s.size, s.size, s.size / 32),
                    gi::interior_blocks(box.surfaces, box.camera, s.size, s.size, 1), 0, 0};
    scoring.noise = gi::reference_noise(truth->standard_error, truth->mean, scoring.blocks).relative_rms;
    scoring.pixel_noise = gi::reference_noise(truth->standard_error, truth->mean, scoring.pixels).relative_rms;
    const gi::View view{box.camera, s.size, s.size, "2 x 2 jittered eye rays (radiosity) or uniform random paths "
                                                    "(path tracing) per pixel, box filter"};

    // 1. Every method on one chart, and what path tracing needs to match each.
    const std::vector<Run> radiosity = lesson15::solve_radiosity(box, s, *truth, scoring);
    const std::vector<Run> paths = lesson15::path_trace(*scene, s, *truth, scoring);
    chart_and_table(radiosity, paths, *truth, scoring, s, lesson);

    // 2. Where each fails, side by side.
    std::cout << '\n';
    where_each_fails(radiosity, paths, *truth, view, lesson);

    // 3. What radiosity cannot draw, and path tracing draws slowly.
    std::cout << '\n';
    lesson15::specular(s, lesson);
    lesson.say("\nimages, tables and the chart: " + lesson.out().string() + "/");
  });
}
