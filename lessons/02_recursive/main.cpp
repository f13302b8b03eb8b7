// Lesson 02 -- recursive ray tracing: Whitted's eye rays, shadow rays, reflected
// and transmitted rays, and the two ways recursion stops: a depth limit and a
// contribution threshold. Each is measured in rays, time and error against a
// deep reference render.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/metrics.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"

namespace {

std::vector<gi::Column> ray_columns(const std::string& first) {
  return {{first}, {"primary"}, {"shadow"}, {"reflected"}, {"transmitted"}, {"total"},
          {"ms", 1},  {"Mrays/s", 2}, {"RMSE", 2, gi::Format::Scientific}, {"PSNR dB", 1}};
}

// A row of rays by kind, time and error against the reference image.
std::vector<gi::Cell> ray_row(const gi::Cell& first, const gi::RenderResult& r, const gi::Image* reference) {
  using K = gi::RayKind;
  const double ms = 1e3 * r.seconds;
  std::vector<gi::Cell> row{first, r.counts.of(K::Primary), r.counts.of(K::Shadow), r.counts.of(K::Reflected),
                            r.counts.of(K::Transmitted), r.counts.total(), ms,
                            r.counts.total() / r.seconds * 1e-6};
  row.push_back(reference ? gi::Cell(gi::rmse(r.image, *reference)) : gi::Cell("-"));
  // A picture equal to its reference has no error to take the logarithm of: PSNR is
  // infinite, shown as the word.
  const double psnr = reference ? gi::psnr(r.image, *reference) : 0;
  row.push_back(!reference ? gi::Cell("-") : std::isfinite(psnr) ? gi::Cell(psnr) : gi::Cell("identical"));
  return row;
}

// Renders `repeat` times and keeps the run with the median time.
gi::RenderResult render_median(const gi::World& world, const gi::RenderSettings& settings, int repeat, int threads,
                               gi::Progress* progress = nullptr) {
  std::vector<gi::RenderResult> runs;
  for (int i = 0; i < repeat; ++i) {
    runs.push_back(gi::render(world, settings, 1, threads));
    if (progress) progress->advance();
  }
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
  return std::move(runs[runs.size() / 2]);
}


// One sweep of the lesson: a table row and a chart point (rays, error) per setting.
struct Sweep {
  gi::Table table;
  gi::Series series;
};

// The camera and pixel sampling of the lesson's pictures.
gi::View view(const gi::World& world, const gi::RenderSettings& settings) {
  return {world.scene.camera, settings.width, settings.height, gi::describe_pixel_samples(settings.sampling)};
}

// Depth limits 0..max_depth against the reference; writes each image.
Sweep depth_sweep(const gi::World& world, gi::RenderSettings settings, int max_depth, int repeat,
                  const gi::RenderResult& reference, gi::Lesson& lesson, gi::Progress& progress) {
  const int threads = lesson.threads();
  Sweep sweep{gi::Table("Depth limits, scene " + world.scene.name + " (reference: depth " +
                            std::to_string(settings.trace.max_depth) + ")",
                        ray_columns("depth")),
              {"depth limit 0.." + std::to_string(max_depth), {}, {}}};
  for (int depth = 0; depth <= max_depth; ++depth) {
    settings.trace.max_depth = depth;
    const gi::RenderResult r = render_median(world, settings, repeat, threads, &progress);
    sweep.table.add_row(ray_row(depth, r, &reference.image));
    sweep.series.x.push_back(static_cast<double>(r.counts.total()));
    sweep.series.y.push_back(gi::rmse(r.image, reference.image));
    lesson.picture(r.image, "depth_" + std::to_string(depth), "depth limit " + std::to_string(depth),
                   view(world, settings));
    if (depth == 1)
      lesson.diagram(gi::difference_image(r.image, reference.image), "diff_depth_1",
                     "|depth 1 - reference| in false colour, red at the largest difference",
                     gi::ColourScale{0, gi::largest_difference(r.image, reference.image), "|difference| in radiance"});
  }
  return sweep;
}

// Contribution thresholds at the reference's depth limit.
Sweep threshold_sweep(const gi::World& world, gi::RenderSettings settings, const std::vector<double>& thresholds,
                      int repeat, int threads, const gi::RenderResult& reference, gi::Progress& progress) {
  Sweep sweep{gi::Table("Contribution thresholds at depth limit " + std::to_string(settings.trace.max_depth),
                        ray_columns("threshold")),
              {"contribution threshold", {}, {}}};
  for (double threshold : thresholds) {
    settings.trace.min_contribution = threshold;
    const gi::RenderResult r = render_median(world, settings, repeat, threads, &progress);
    sweep.table.add_row(ray_row(threshold, r, &reference.image));
    sweep.series.x.push_back(static_cast<double>(r.counts.total()));
    sweep.series.y.push_back(gi::rmse(r.image, reference.image));
  }
  return sweep;
}

gi::Table rays_per_depth(const gi::RayCounts& counts) {
  gi::Table table("Rays cast at each depth in the reference render", {{"depth"}, {"rays"}, {"share %", 2}});
  for (int depth = 0; depth <= gi::RayCounts::max_depth && counts.at_depth(depth) > 0; ++depth)
    table.add_row({depth, counts.at_depth(depth), 100.0 * counts.at_depth(depth) / counts.total()});
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("02_recursive",
                    "Whitted ray tracing at depth limits 0..N and contribution thresholds, against a deep reference.",
                    {.seed = false});
  // Brute force by default: lesson 02 comes before the tree (lab 5), and on its scenes of
  // a dozen objects testing every one, four spheres at a time, is the fastest way
  // (docs/02_recursive.md, "Speed").
  std::string accel = "brute-force";
  gi::RenderSettings settings;
  std::string scene_name = "whitted";
  gi::Scene scene;
  std::optional<int> single_depth;
  int max_depth = 8, reference_depth = 30, repeat = 3;
  lesson.add_image_size(settings.width, settings.height);
  lesson.options()
      .add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names());
  lesson.add_scene(scene_name, scene);
  lesson.options()
      .add("--max-depth", max_depth, "sweep depth limits 0..N", 0, 40)
      .add("--reference-depth", reference_depth, "depth limit of the reference render", 1, 60)
      .add_optional("--depth", single_depth, "render once at this depth limit instead of the sweep", 0, 60)
      .add("--repeat", repeat, "renders per measurement; the median time is reported", 1, 50)
      .add_flag("--fast-queries", settings.trace.fast_queries,
                "ray queries and local shading by the tuned *_fast files (world_fast.cpp, whitted_fast.cpp): the same picture, sooner");
  return lesson.run(argc, argv, [&] {
    const gi::World world = gi::make_world(scene, gi::acceleration_from_name(accel));

    if (single_depth) {  // one render, for timing against another renderer
      settings.trace.max_depth = *single_depth;
      const gi::RenderResult r = render_median(world, settings, repeat, lesson.threads());
      const std::string stem = gi::file_stem(scene.name) + "_depth_" + std::to_string(*single_depth);
      gi::Table table("Scene " + scene.name + ", depth limit " + std::to_string(*single_depth) + ", " +
                          std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", median of " +
                          std::to_string(repeat),
                      ray_columns("depth"));
      table.add_row(ray_row(*single_depth, r, nullptr));
      lesson.table(table, stem);
      lesson.picture(r.image, stem, "scene " + scene.name + " at depth limit " + std::to_string(*single_depth),
                     view(world, settings));
      return;
    }

    const std::vector<double> thresholds{0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.003, 0.001};
    gi::Progress progress("rendering", 1 + (max_depth + 1 + static_cast<long long>(thresholds.size())) * repeat);
    settings.trace.max_depth = reference_depth;
    const gi::RenderResult reference = gi::render(world, settings, 1, lesson.threads());
    progress.advance();
    lesson.picture(reference.image, "reference", "the reference: depth limit " + std::to_string(reference_depth),
                   view(world, settings));
    const Sweep depths = depth_sweep(world, settings, max_depth, repeat, reference, lesson, progress);
    const Sweep cutoffs = threshold_sweep(world, settings, thresholds, repeat, lesson.threads(), reference, progress);
    progress.finish();

    lesson.table(depths.table, "depth_limits");
    std::cout << '\n';
    lesson.table(rays_per_depth(reference.counts), "rays_per_depth");
    std::cout << '\n';
    lesson.table(cutoffs.table, "thresholds");
    std::cout << '\n';
    // Against rays cast, the work itself: the same on every machine and every run,
    // where the milliseconds of a render this small are mostly noise.
    const gi::Chart chart{"Stopping recursion: error against rays cast (" + scene.name + ")", "rays cast",
                          "RMSE against the reference", false, true, {depths.series, cutoffs.series}};
    lesson.chart(chart, "error_vs_rays");
    lesson.say("images and charts: " + lesson.out().string() + "/");
  });
}
