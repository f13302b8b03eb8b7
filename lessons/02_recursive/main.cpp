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
gi::RenderResult render_median(const gi::Scene& scene, const gi::RenderSettings& settings, int repeat) {
  std::vector<gi::RenderResult> runs;
  for (int i = 0; i < repeat; ++i) runs.push_back(gi::render(scene, settings));
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
  return std::move(runs[runs.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("02_recursive", [&] {
    gi::CommonOptions common;
    gi::RenderSettings settings;
    std::string scene_name = "whitted";
    std::optional<int> single_depth;
    int max_depth = 8, reference_depth = 30, repeat = 3;
    gi::Options options("02_recursive",
                        "Whitted ray tracing at depth limits 0..N and contribution thresholds, against a deep reference.");
    gi::add_common_options(options, common, "02_recursive");
    options.add("--width", settings.width, "image width in pixels", 1, 8192)
        .add("--height", settings.height, "image height in pixels", 1, 8192)
        .add("--scene", scene_name, "scene to render", gi::scene_names())
        .add("--max-depth", max_depth, "sweep depth limits 0..N", 0, 40)
        .add("--reference-depth", reference_depth, "depth limit of the reference render", 1, 60)
        .add_optional("--depth", single_depth, "render once at this depth limit instead of the sweep", 0, 60)
        .add("--repeat", repeat, "renders per measurement; the median time is reported", 1, 50);
    if (!options.parse(argc, argv)) return 0;
    settings.threads = common.threads;
    const gi::Scene scene = gi::make_scene(scene_name);
    const std::string out = common.out;

    if (single_depth) {  // one render, for timing against another renderer
      settings.trace.max_depth = *single_depth;
      const gi::RenderResult r = render_median(scene, settings, repeat);
      gi::Table table("Scene " + scene_name + ", depth limit " + std::to_string(*single_depth) + ", " +
                          std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", median of " +
                          std::to_string(repeat),
                      ray_columns("depth"));
      table.add_row(ray_row(*single_depth, r, nullptr));
      table.print();
      gi::write_png(r.image, out + "/" + scene_name + "_depth_" + std::to_string(*single_depth) + ".png");
      return 0;
    }

    settings.trace.max_depth = reference_depth;
    const gi::RenderResult reference = gi::render(scene, settings);
    gi::write_png(reference.image, out + "/reference.png");

    gi::Table by_depth("Depth limits, scene " + scene_name + " (reference: depth " + std::to_string(reference_depth) + ")",
                       ray_columns("depth"));
    gi::Series depth_series{"depth limit 0.." + std::to_string(max_depth), {}, {}};
    for (int depth = 0; depth <= max_depth; ++depth) {
      settings.trace.max_depth = depth;
      const gi::RenderResult r = render_median(scene, settings, repeat);
      by_depth.add_row(ray_row(depth, r, &reference.image));
      depth_series.x.push_back(1e3 * r.seconds);
      depth_series.y.push_back(gi::rmse(r.image, reference.image));
      gi::write_png(r.image, out + "/depth_" + std::to_string(depth) + ".png");
      if (depth == 1) gi::write_png(gi::difference_image(r.image, reference.image), out + "/diff_depth_1.png");
    }
    by_depth.print();
    by_depth.write_csv(out + "/depth_limits.csv");

    gi::Table per_depth("Rays cast at each depth in the reference render", {{"depth"}, {"rays"}, {"share %", 2}});
    for (int depth = 0; depth <= reference_depth && reference.counts.at_depth(depth) > 0; ++depth)
      per_depth.add_row({depth, reference.counts.at_depth(depth),
                         100.0 * reference.counts.at_depth(depth) / reference.counts.total()});
    std::cout << '\n';
    per_depth.print();
    per_depth.write_csv(out + "/rays_per_depth.csv");

    gi::Table by_threshold("Contribution thresholds at depth limit " + std::to_string(reference_depth),
                           ray_columns("threshold"));
    gi::Series threshold_series{"contribution threshold", {}, {}};
    for (double threshold : {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.003, 0.001}) {
      settings.trace.max_depth = reference_depth;
      settings.trace.min_contribution = threshold;
      const gi::RenderResult r = render_median(scene, settings, repeat);
      by_threshold.add_row(ray_row(threshold, r, &reference.image));
      threshold_series.x.push_back(1e3 * r.seconds);
      threshold_series.y.push_back(gi::rmse(r.image, reference.image));
    }
    std::cout << '\n';
    by_threshold.print();
    by_threshold.write_csv(out + "/thresholds.csv");

    gi::Chart chart{"Stopping recursion: error against time (" + scene_name + ")", "render time (ms)",
                    "RMSE against the reference", false, true, {depth_series, threshold_series}};
    gi::write_svg(chart, out + "/error_vs_time.svg");
    std::cout << "\nimages and charts: " << out << "/\n";
    return 0;
  });
}
