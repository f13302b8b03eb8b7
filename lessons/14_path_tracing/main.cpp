// Lesson 14 -- the rendering equation, solved by Monte Carlo path tracing. First
// Monte Carlo itself (a 1-D integral, then the hemisphere, uniform against cosine
// sampling); then the Cornell box at 1, 4, 16, ... samples per pixel against a converged
// reference, with each picture's own variance; then BSDF sampling alone, light sampling
// alone and both with MIS, error against time; last, Veach's glossy plates, where each
// strategy alone fails somewhere and MIS does not; last, the numbers the paths read:
// independent, stratified and Sobol', error against samples per pixel.
// The steps are below; converge.cpp runs one strategy on one film, reference.cpp makes
// what each picture is measured against, monte_carlo.cpp is step 1, veach_plates.cpp
// step 5 and sequences.cpp step 6.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "converge.hpp"
#include "gi/image/metrics.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "monte_carlo.hpp"
#include "reference.hpp"
#include "sequences.hpp"
#include "veach_plates.hpp"

namespace {

using lesson14::converge;
using lesson14::mean_of;
using lesson14::Settings;
using lesson14::Snapshot;

// The pictures' table: MIS from 1 spp on, its error against the reference and the
// error its own variance predicts, sqrt(mean variance + the reference's).
void picture_table(const std::vector<Snapshot>& mis, const gi::Truth& reference, const Settings& s,
                   gi::Lesson& lesson) {
  const std::string numbers =
      s.sequence == gi::SamplerKind::Independent ? "" : std::string(", ") + gi::sequence_name(s.sequence) + " numbers";
  gi::Table table("Path tracing (MIS" + numbers + "), " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                      ": a convergence study against the reference (the same estimator, many more samples)",
                  {{"spp"},
                   {"time (s)", 3},
                   {"Msamples/s", 2},
                   {"RMSE", 2, gi::Format::Scientific},
                   {"rel. RMS", 2, gi::Format::Scientific},
                   {"mean variance", 2, gi::Format::Scientific},
                   {"sqrt(var + ref var)", 2, gi::Format::Scientific}});
  gi::Image squared = reference.standard_error;
  for (gi::Pixel& p : squared.pixels) p *= p;
  const double reference_variance = mean_of(squared);
  for (const Snapshot& shot : mis) {
    const double rate = 1e-6 * shot.spp * s.width * s.height / shot.seconds;
    if (shot.spp < 2)  // one sample says nothing about its spread
      table.add_row({shot.spp, shot.seconds, rate, shot.rmse, shot.relative, "-", "-"});
    else
      table.add_row({shot.spp, shot.seconds, rate, shot.rmse, shot.relative, shot.variance,
                     std::sqrt(shot.variance + reference_variance)});
  }
  lesson.table(table, "pictures");
}

// The strategies' table: each at the last snapshot, and its efficiency 1 / (RMSE^2 t),
// which does not change with the sample count (RMSE^2 falls as 1 / t). An estimate
// without error (the furnace at --max-depth 0 sees only emission) has no efficiency
// to compare: "exact".
void strategy_rows(gi::Table& table, const std::string& scene, const std::vector<std::vector<Snapshot>>& runs) {
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Snapshot& last = runs[k].back();
    const double efficiency = 1 / (last.rmse * last.rmse * last.seconds);
    table.add_row({scene, gi::strategy_names()[k], last.spp, last.seconds, last.rmse,
                   std::isfinite(efficiency) ? gi::Cell(efficiency) : gi::Cell(last.rmse == 0 ? "exact" : "-")});
  }
}

// 2. The pictures, MIS at 1, 2, 4, ... spp, against the reference: the camera, the
//    reference, every strategy's snapshots (MIS's pictures drawn) and MIS's table.
std::vector<std::vector<Snapshot>> pictures(const gi::PathScene& scene, const Settings& s,
                                            std::optional<gi::Truth>& reference, gi::Lesson& lesson) {
  const gi::Camera& camera = scene.scene().camera;
  const auto point = [](const gi::vec3& p) {
    return "(" + gi::format_number(p.x, 1, gi::Format::Fixed) + ", " + gi::format_number(p.y, 1, gi::Format::Fixed) +
           ", " + gi::format_number(p.z, 1, gi::Format::Fixed) + ")";
  };
  lesson.say("\ncamera: eye " + point(camera.eye) + ", looking at " + point(camera.look_at) + ", up " +
             point(camera.up) + ", vertical field of view " +
             gi::format_number(camera.vertical_fov, 4, gi::Format::Fixed) +
             " degrees; square pixels, each the mean over its area (a box filter)");
  if (!reference) reference = lesson14::own_reference(scene, s, lesson);
  lesson.say("reference: " + reference->about_value("scene") + ", " + std::to_string(reference->spp) + " spp (" +
             reference->about_value("strategy") + ", seed " + std::to_string(reference->seed) + ") at " +
             std::to_string(s.width) + "x" + std::to_string(s.height) + "; its own relative standard error " +
             gi::format_number(100 * gi::relative_standard_error(reference->standard_error, reference->mean), 2,
                               gi::Format::Fixed) +
             "% per pixel\n");
  std::vector<std::vector<Snapshot>> runs;
  for (const gi::Strategy strategy : {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis})
    runs.push_back(converge(scene, s, strategy, *reference, strategy == gi::Strategy::Mis ? &lesson : nullptr));
  picture_table(runs.back(), *reference, s, lesson);
  return runs;
}

// 3. The three strategies: on this scene, and on the white furnace, whose lights are
//    as large as can be -- where BSDF sampling wins and MIS must follow it. Its picture
//    is the same everywhere, so a small one tells as much.
void strategies(const Settings& s, const std::vector<std::vector<Snapshot>>& runs, gi::Lesson& lesson) {
  const gi::PathScene furnace = gi::make_path_scene(gi::furnace_scene(0.5, 1.0));
  Settings small = s;
  small.width = small.height = 32;
  std::vector<std::vector<Snapshot>> furnace_runs;
  for (const gi::Strategy strategy : {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis})
    furnace_runs.push_back(converge(furnace, small, strategy, lesson14::furnace_truth(small), nullptr));
  gi::Table strategies("The three strategies: RMSE against " + s.scene +
                           "'s reference and the furnace's closed "
                           "form (bsdf and lights: estimators independent of the reference)",
                       {{"scene"},
                        {"strategy"},
                        {"spp"},
                        {"time (s)", 3},
                        {"RMSE", 2, gi::Format::Scientific},
                        {"efficiency 1/(RMSE^2 s)", 3, gi::Format::Scientific}});
  strategy_rows(strategies, s.scene, runs);
  strategy_rows(strategies, "furnace", furnace_runs);
  std::cout << '\n';
  lesson.table(strategies, "strategies");
  std::vector<gi::Series> curves;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    gi::Series curve{gi::strategy_names()[k], {}, {}};
    for (const Snapshot& shot : runs[k]) curve.x.push_back(shot.seconds), curve.y.push_back(shot.rmse);
    curves.push_back(curve);
  }
  // The Monte Carlo rate through MIS's first point: RMSE falling as time^(-1/2).
  const std::vector<Snapshot>& mis = runs.back();
  gi::Series slope{"slope -1/2", {}, {}, gi::Mark::Line};
  for (const Snapshot& shot : {mis.front(), mis.back()})
    slope.x.push_back(shot.seconds),
        slope.y.push_back(mis.front().rmse * std::sqrt(mis.front().seconds / shot.seconds));
  curves.push_back(slope);
  lesson.chart({"Path tracing " + s.scene + ": error against time", "render time (s)", "RMSE against the reference",
                true, true, curves},
               "error_vs_time");
}

// 4. Speed, in the unit docs/15 compares with Blender's Cycles on the same box: ms per
//    sample per pixel at 256x256.
void speed(const Settings& s, const std::vector<Snapshot>& mis, gi::Lesson& lesson) {
  const double rate = mis.back().spp * double(s.width) * s.height / mis.back().seconds;
  lesson.say("\nspeed: " + gi::format_number(1e-6 * rate, 2, gi::Format::Fixed) + " M samples/s with MIS = " +
             gi::format_number(1e3 * 256 * 256 / rate, 1, gi::Format::Fixed) +
             " ms per sample per pixel at 256x256, on " + (s.threads ? std::to_string(s.threads) : "all") +
             " threads (against Blender's Cycles: docs/15, \"Speed\")");
  lesson.say("images: " + lesson.out().string() + "/ (" + s.scene + "_<spp>spp.png and .pfm, progression.png: 1, " +
             "4, 16 ... spp and the reference; relative_error_" + std::to_string(s.max_spp) +
             "spp.png, error_vs_time.svg)");
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("14_path_tracing", "Path tracing the rendering equation: Monte Carlo, pictures at 1 to "
                                       "4096 samples per pixel against a converged reference, BSDF "
                                       "sampling, light sampling and MIS, error against time, and independent, "
                                       "stratified and Sobol' numbers, error against samples.");
  Settings s;
  lesson14::PlatesSettings plates;
  std::string sequence = "independent";
  s.reference = std::string(GI_SOURCE_DIR) + "/lessons/references/cornell_256x256";
  lesson.add_image_size(s.width, s.height);
  lesson.options()
      .add("--scene", s.scene, "scene to render", gi::path_scene_names())
      .add("--max-spp", s.max_spp, "the last picture's samples per pixel (1, 2, 4, ... up to it)", 1, 1 << 16)
      .add("--max-depth", s.path.max_depth, "bounces per path", 0, 10000)
      .add("--reference", s.reference, "the Cornell box's converged picture (files STEM.txt, STEM.pfm, ...)")
      .add("--reference-spp", s.reference_spp, "samples per pixel of a reference this lesson renders itself", 16,
           1 << 20)
      .add("--plates-spp", plates.spp, "samples per pixel of each strategy on Veach's plates (step 5)", 1, 1 << 12)
      .add("--sampler", sequence, "the numbers the pictures' paths read (step 2)", gi::sequence_option_names());
  std::optional<gi::PathScene> scene;
  std::optional<gi::Truth> reference, sequences_reference;
  lesson.add_check([&] {  // before any work: a missing, damaged or stale reference is said at once
    scene.emplace(gi::make_path_scene(gi::make_path_scene_by_name(s.scene)));
    if (lesson14::uses_stored_reference(s))
      reference = gi::stored_truth_at(s.reference, "cornell", 256, s.width, s.height);
    const int side = lesson14::sequence_settings(s.width, s.height, s.max_spp).side;  // step 6's
    sequences_reference = gi::stored_truth_at(s.reference, "cornell", 256, side, side);
  });
  return lesson.run(argc, argv, [&] {
    s.threads = lesson.threads();
    s.seed = lesson.seed();
    s.sequence = gi::sequence_from_name(sequence);
    lesson14::monte_carlo_warm_up(s, lesson);  // 1. monte_carlo.cpp
    const std::vector<std::vector<Snapshot>> runs = pictures(*scene, s, reference, lesson);
    strategies(s, runs, lesson);
    speed(s, runs.back(), lesson);
    plates.width = s.width, plates.threads = s.threads, plates.seed = s.seed;
    lesson14::veach_plates(plates, lesson);  // 5. veach_plates.cpp
    lesson14::SequenceSettings numbers = lesson14::sequence_settings(s.width, s.height, s.max_spp);
    numbers.threads = s.threads, numbers.seed = s.seed;
    lesson14::sequences(numbers, *sequences_reference, lesson);  // 6. sequences.cpp
  });
}
