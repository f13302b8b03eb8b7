// Lesson 02 -- recursive ray tracing: Whitted's eye rays, shadow rays, reflected
// and transmitted rays, and the two ways recursion stops: a depth limit and a
// contribution threshold. Each is measured in rays, time and error against a
// deep reference render.
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/image/metrics.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/builtin_scenes.hpp"

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
  row.push_back(reference ? gi::Cell(gi::psnr(r.image, *reference)) : gi::Cell("-"));
  return row;
}

// Renders `repeat` times and keeps the run with the median time.
gi::RenderResult render_median(const gi::World& world, const gi::RenderSettings& settings, int repeat,
                               gi::Progress* progress = nullptr) {
  std::vector<gi::RenderResult> runs;
  for (int i = 0; i < repeat; ++i) {
    runs.push_back(gi::render(world, settings));
    if (progress) progress->advance();
  }
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
  return std::move(runs[runs.size() / 2]);
}


// One sweep of the lesson: a table row and a chart point per setting.
struct Sweep {
  gi::Table table;
  gi::Series series;
};

// Depth limits 0..max_depth against the reference; writes each image.
Sweep depth_sweep(const gi::World& world, gi::RenderSettings settings, int max_depth, int repeat,
                  const gi::RenderResult& reference, const std::string& out, gi::Progress& progress) {
  Sweep sweep{gi::Table("Depth limits, scene " + world.scene.name + " (reference: depth " +
                            std::to_string(settings.trace.max_depth) + ")",
                        ray_columns("depth")),
              {"depth limit 0.." + std::to_string(max_depth), {}, {}}};
  for (int depth = 0; depth <= max_depth; ++depth) {
    settings.trace.max_depth = depth;
    const gi::RenderResult r = render_median(world, settings, repeat, &progress);
    sweep.table.add_row(ray_row(depth, r, &reference.image));
    sweep.series.x.push_back(1e3 * r.seconds);
    sweep.series.y.push_back(gi::rmse(r.image, reference.image));
    gi::write_png(r.image, out + "/depth_" + std::to_string(depth) + ".png");
    if (depth == 1) gi::write_png(gi::difference_image(r.image, reference.image), out + "/diff_depth_1.png");
  }
  return sweep;
}

// Contribution thresholds at the reference's depth limit.
Sweep threshold_sweep(const gi::World& world, gi::RenderSettings settings, const std::vector<double>& thresholds,
                      int repeat, const gi::RenderResult& reference, gi::Progress& progress) {
  Sweep sweep{gi::Table("Contribution thresholds at depth limit " + std::to_string(settings.trace.max_depth),
                        ray_columns("threshold")),
              {"contribution threshold", {}, {}}};
  for (double threshold : thresholds) {
    settings.trace.min_contribution = threshold;
    const gi::RenderResult r = render_median(world, settings, repeat, &progress);
    sweep.table.add_row(ray_row(threshold, r, &reference.image));
    sweep.series.x.push_back(1e3 * r.seconds);
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
  return gi::run_lesson("02_recursive", [&] {
    gi::CommonOptions common;
    std::string accel = "bvh";  // a kit without lab 5 done can still render by brute force
    gi::RenderSettings settings;
    std::string scene_name = "whitted";
    std::optional<int> single_depth;
    int max_depth = 8, reference_depth = 30, repeat = 3;
    gi::Options options("02_recursive",
                        "Whitted ray tracing at depth limits 0..N and contribution thresholds, against a deep reference.");
    gi::add_common_options(options, common, "02_recursive");
    options.add("--width", settings.width, "image width in pixels", 1, 8192)
        .add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names())
        .add("--height", settings.height, "image height in pixels", 1, 8192)
        .add("--scene", scene_name, "scene to render", gi::scene_names())
        .add("--max-depth", max_depth, "sweep depth limits 0..N", 0, 40)
        .add("--reference-depth", reference_depth, "depth limit of the reference render", 1, 60)
        .add_optional("--depth", single_depth, "render once at this depth limit instead of the sweep", 0, 60)
        .add("--repeat", repeat, "renders per measurement; the median time is reported", 1, 50);
    if (!options.parse(argc, argv)) return 0;
    settings.threads = common.threads;
    const gi::World world = gi::make_world(gi::make_scene(scene_name), gi::acceleration_from_name(accel));
    const std::string out = common.out;

    if (single_depth) {  // one render, for timing against another renderer
      settings.trace.max_depth = *single_depth;
      const gi::RenderResult r = render_median(world, settings, repeat);
      gi::Table table("Scene " + scene_name + ", depth limit " + std::to_string(*single_depth) + ", " +
                          std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", median of " +
                          std::to_string(repeat),
                      ray_columns("depth"));
      table.add_row(ray_row(*single_depth, r, nullptr));
      table.print();
      gi::write_png(r.image, out + "/" + scene_name + "_depth_" + std::to_string(*single_depth) + ".png");
      return 0;
    }

    const std::vector<double> thresholds{0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.003, 0.001};
    gi::Progress progress("rendering", 1 + (max_depth + 1 + static_cast<long long>(thresholds.size())) * repeat);
    settings.trace.max_depth = reference_depth;
    const gi::RenderResult reference = gi::render(world, settings);
    progress.advance();
    gi::write_png(reference.image, out + "/reference.png");
    const Sweep depths = depth_sweep(world, settings, max_depth, repeat, reference, out, progress);
    const Sweep cutoffs = threshold_sweep(world, settings, thresholds, repeat, reference, progress);
    progress.finish();

    const gi::Table per_depth = rays_per_depth(reference.counts);
    for (const gi::Table* table : {&depths.table, &per_depth, &cutoffs.table}) {
      table->print();
      std::cout << '\n';
    }
    depths.table.write_csv(out + "/depth_limits.csv");
    per_depth.write_csv(out + "/rays_per_depth.csv");
    cutoffs.table.write_csv(out + "/thresholds.csv");
    const gi::Chart chart{"Stopping recursion: error against time (" + scene_name + ")", "render time (ms)",
                          "RMSE against the reference", false, true, {depths.series, cutoffs.series}};
    gi::write_svg(chart, out + "/error_vs_time.svg");
    std::cout << "images and charts: " << out << "/\n";
    return 0;
  });
}
