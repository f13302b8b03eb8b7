// Lesson 03 -- aliasing and its cures: one ray per pixel against direct
// supersampling, stochastic (random) sampling, jittering and Whitted's adaptive
// supersampling, at several sample budgets, each measured against a reference
// made with many jittered samples. Error against time, per method.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/image/metrics.hpp"
#include "gi/raytrace/reference.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"

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

gi::View view(const gi::World& world, const gi::RenderSettings& settings) {
  return {world.scene.camera, settings.width, settings.height, gi::describe_pixel_samples(settings.sampling)};
}

// The reference: many jittered samples per pixel, computed once and kept in the
// output folder (reference.hpp says when it is trusted).
gi::Image reference_image(const gi::World& world, gi::RenderSettings settings, int n, gi::Lesson& lesson) {
  settings.sampling = {gi::Sampler::Jittered, n};
  const std::uint64_t seed = lesson.seed() + 1000;  // independent of the jittered runs being measured
  const std::string scene_key = "scene " + world.scene.name + ", fingerprint " + gi::fingerprint(world.scene);
  gi::CachedTruth cached = gi::cached_reference(world, settings, seed, lesson.threads(), scene_key, lesson.out());
  if (cached.from_cache) lesson.say("reference: read from the cache " + cached.stem.string() + ".*\n");
  else if (cached.reason != "none kept") lesson.say("reference: rendered again, " + cached.reason + "\n");
  for (const auto& file : gi::truth_files(cached.stem)) lesson.record(file, gi::OutputKind::Cache, "the cached reference");
  lesson.picture(cached.truth.mean, "reference",
                 "the reference: jittered " + std::to_string(n) + "x" + std::to_string(n), view(world, settings));
  return std::move(cached.truth.mean);
}

std::string slug(std::string label) {
  std::replace(label.begin(), label.end(), ' ', '_');
  return label;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("03_antialiasing", "Anti-aliasing: grid, random, jittered and adaptive supersampling "
                                       "against a many-sample reference.");
  std::string accel = "bvh";  // a kit without lab 5 done can still render by brute force
  gi::RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.trace.max_depth = 3;
  std::string scene_name = "aliasing";
  gi::Scene scene;
  int reference_n = 16;
  lesson.add_image_size(settings.width, settings.height);
  lesson.options()
      .add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names());
  lesson.add_scene(scene_name, scene);
  lesson.options()
      .add("--depth", settings.trace.max_depth, "recursion depth limit", 0, 30)
      .add("--reference-n", reference_n, "reference: jittered n x n samples per pixel", 4, 64);
  return lesson.run(argc, argv, [&] {
    const gi::World world = gi::make_world(scene, gi::acceleration_from_name(accel));
    const gi::Image reference = reference_image(world, settings, reference_n, lesson);

    gi::Table table("Anti-aliasing, scene " + scene.name + ", against jittered " + std::to_string(reference_n) + "x" +
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
      const gi::RenderResult r = gi::render(world, settings, lesson.seed(), lesson.threads());
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
          lesson.diagram(gi::false_colour(counts, settings.width, settings.height, 0, s.back()),
                         "adaptive_samples_heatmap", "eye rays per pixel of adaptive 0.05, black 0 to red the most",
                         gi::ColourScale{0, double(s.back()), "eye rays per pixel"});
        }
      }
      const bool sixteen = m.sampling.n == 4 || m.sampling.sampler == gi::Sampler::Centre ||
                           (m.sampling.sampler == gi::Sampler::Adaptive && m.sampling.threshold == 0.05);
      if (sixteen) {
        lesson.picture(r.image, slug(m.label), m.label, view(world, settings));
        crops.push_back(crop(r.image));
      }
    }
    progress.finish();
    crops.push_back(crop(reference));
    lesson.diagram(gi::side_by_side(crops), "edge_crops",
                   "a window at the horizon, 4x: centre, grid, random, jittered, adaptive 0.05, reference");

    lesson.table(table, "antialiasing");
    std::cout << '\n';
    lesson.table(adaptive, "adaptive");
    lesson.chart({"Anti-aliasing: error against time (" + scene.name + ")", "render time (ms)",
                  "RMSE against the reference", true, true, curves},
                 "error_vs_time");
    lesson.say("\nimages and charts: " + lesson.out().string() + "/ (edge_crops.png: centre, grid, random, jittered, " +
               "adaptive 0.05, reference)");
  });
}
