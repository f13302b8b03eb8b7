// Lesson 03 -- aliasing and its cures: one ray per pixel against direct
// supersampling, stochastic (random) sampling, jittering and Whitted's adaptive
// supersampling, at several sample budgets, each measured against a reference
// made with many jittered samples. Error against time, per method.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/image/metrics.hpp"
#include "gi/raytrace/reference.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/builtin_scenes.hpp"

namespace {

struct Method {
  std::string label;  // "jittered 4x4"
  gi::Sampling sampling;
};

// Every method at every budget the lesson compares.
std::vector<Method> methods() {
  std::vector<Method> list{{"centre", {gi::Sampler::Centre, 1}}};
  for (gi::Sampler s : {gi::Sampler::Grid, gi::Sampler::Random, gi::Sampler::Jittered})
    for (int n : {2, 3, 4, 6})
      list.push_back({gi::sampler_name(s) + " " + std::to_string(n) + "x" + std::to_string(n), {s, n}});
  for (double threshold : {0.2, 0.1, 0.05, 0.02})
    list.push_back({"adaptive " + gi::format_number(threshold, 2, gi::Format::Fixed),
                    {gi::Sampler::Adaptive, 1, threshold, 3}});
  return list;
}

// The reference: many jittered samples per pixel, computed once and kept in out/.
gi::Image reference_image(const gi::World& world, gi::RenderSettings settings, int n, const std::string& out) {
  settings.sampling = {gi::Sampler::Jittered, n};
  settings.seed += 1000;  // independent of the jittered runs being measured
  const gi::CachedImage cached = gi::cached_reference(world, settings, "built-in scene " + world.scene.name, out);
  if (cached.from_cache) std::cout << "reference: read from the cache " << cached.file.string() << "\n\n";
  const gi::Image& reference = cached.image;
  gi::write_png(reference, out + "/reference.png");
  return reference;
}

std::string slug(std::string label) {
  std::replace(label.begin(), label.end(), ' ', '_');
  return label;
}

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("03_antialiasing", [&] {
    gi::CommonOptions common;
    std::string accel = "bvh";  // a kit without lab 5 done can still render by brute force
    gi::RenderSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.trace.max_depth = 3;
    std::string scene_name = "aliasing";
    int reference_n = 16;
    gi::Options options("03_antialiasing", "Anti-aliasing: grid, random, jittered and adaptive supersampling "
                                           "against a many-sample reference.");
    gi::add_common_options(options, common, "03_antialiasing");
    options.add("--width", settings.width, "image width in pixels", 16, 4096)
        .add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names())
        .add("--height", settings.height, "image height in pixels", 16, 4096)
        .add("--scene", scene_name, "scene to render", gi::scene_names())
        .add("--depth", settings.trace.max_depth, "recursion depth limit", 0, 30)
        .add("--reference-n", reference_n, "reference: jittered n x n samples per pixel", 4, 64);
    if (!options.parse(argc, argv)) return 0;
    settings.threads = common.threads;
    settings.seed = common.seed;
    const gi::World world = gi::make_world(gi::make_scene(scene_name), gi::acceleration_from_name(accel));
    const std::string out = common.out;
    const gi::Image reference = reference_image(world, settings, reference_n, out);

    gi::Table table("Anti-aliasing, scene " + scene_name + ", against jittered " + std::to_string(reference_n) + "x" +
                        std::to_string(reference_n),
                    {{"method"}, {"spp", 2}, {"eye rays"}, {"ms", 1}, {"RMSE", 2, gi::Format::Scientific},
                     {"PSNR dB", 1}});
    gi::Table adaptive("Adaptive supersampling: eye rays per pixel",
                       {{"threshold"}, {"min"}, {"median"}, {"max"}, {"pixels split %", 1}});
    std::vector<gi::Series> curves;
    std::vector<gi::Image> crops;
    // An edge-rich window at the horizon, enlarged 4x, for every method at 16 spp.
    const int cw = settings.width / 8, ch = settings.height / 8;
    const int cx = settings.width / 2 - cw / 2, cy = static_cast<int>(settings.height * 0.42);
    auto crop = [&](const gi::Image& image) { return gi::enlarge(gi::crop(image, cx, cy, cw, ch), 4); };

    const std::vector<Method> list = methods();
    gi::Progress progress("rendering", static_cast<long long>(list.size()));
    for (const Method& m : list) {
      settings.sampling = m.sampling;
      const gi::RenderResult r = gi::render(world, settings);
      progress.advance();
      const double spp = r.counts.of(gi::RayKind::Primary) / double(r.image.pixels.size());
      table.add_row({m.label, spp, r.counts.of(gi::RayKind::Primary), 1e3 * r.seconds, gi::rmse(r.image, reference),
                     gi::psnr(r.image, reference)});
      const std::string family = gi::sampler_name(m.sampling.sampler);
      if (curves.empty() || curves.back().name != family) curves.push_back({family, {}, {}});
      curves.back().x.push_back(1e3 * r.seconds);
      curves.back().y.push_back(gi::rmse(r.image, reference));
      if (m.sampling.sampler == gi::Sampler::Adaptive) {
        std::vector<int> s = r.samples;
        std::sort(s.begin(), s.end());
        const double split = 100.0 * (s.end() - std::upper_bound(s.begin(), s.end(), 4)) / s.size();
        adaptive.add_row({m.label.substr(9), s.front(), s[s.size() / 2], s.back(), split});
        if (m.sampling.threshold == 0.05) {
          const std::vector<double> counts(r.samples.begin(), r.samples.end());
          gi::write_png(gi::false_colour(counts, settings.width, settings.height, 0, s.back()),
                        out + "/adaptive_samples_heatmap.png");
        }
      }
      const bool sixteen = m.sampling.n == 4 || m.sampling.sampler == gi::Sampler::Centre ||
                           (m.sampling.sampler == gi::Sampler::Adaptive && m.sampling.threshold == 0.05);
      if (sixteen) {
        gi::write_png(r.image, out + "/" + slug(m.label) + ".png");
        crops.push_back(crop(r.image));
      }
    }
    progress.finish();
    crops.push_back(crop(reference));
    gi::write_png(gi::side_by_side(crops), out + "/edge_crops.png");

    table.print();
    std::cout << '\n';
    adaptive.print();
    table.write_csv(out + "/antialiasing.csv");
    adaptive.write_csv(out + "/adaptive.csv");
    gi::write_svg({"Anti-aliasing: error against time (" + scene_name + ")", "render time (ms)",
                   "RMSE against the reference", true, true, curves},
                  out + "/error_vs_time.svg");
    std::cout << "\nimages and charts: " << out << "/ (edge_crops.png: centre, grid, random, jittered, "
              << "adaptive 0.05, reference)\n";
    return 0;
  });
}
