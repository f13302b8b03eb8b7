// Lesson 04 -- soft shadows: an area light sampled by jittered (or random) shadow
// rays. The penumbra grows with the light as similar triangles predict; the noise
// falls with the number of shadow rays, faster when they are jittered, and faster
// again when the numbers they read are stratified or Sobol' (step 3, sequences.cpp).
#include <algorithm>
#include <functional>
#include <optional>
#include <iostream>
#include <string>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/image/metrics.hpp"
#include "gi/raytrace/reference.hpp"
#include "gi/raytrace/shading.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/scene_file.hpp"
#include "gi/scene/soft_shadow_scene.hpp"
#include "sequences.hpp"

namespace {

// A picture on a film of its own, whose samples read `sequence`'s numbers.
gi::RenderResult render_with(const gi::World& world, const gi::RenderSettings& settings, gi::SamplerKind sequence,
                             const gi::Lesson& lesson) {
  gi::Film film = gi::make_film(settings.width, settings.height, lesson.seed(), sequence);
  return gi::render(world, settings, film, lesson.threads());
}

// The part of the area light seen from the floor point (x, 0, 0), by 32 x 32
// jittered shadow rays.
double visible_fraction(const gi::World& world, double x, gi::Rng& rng) {
  const gi::vec3 point(x, 0, 0), up(0, 1, 0);
  const auto reaches = [&](const gi::vec3& y) { return gi::visible(world, point, up, y, 1e-6); };
  const auto one = [](const gi::vec3&) { return gi::Color(1.0); };
  const auto samples = gi::light_samples({gi::LightSampling::Jittered, 32}, rng);
  return gi::soft_shadow_estimate(world.scene.area_lights.front(), samples, reaches, one).x;
}

// Width of the penumbra of the box's edge on the floor along z = 0: where the visible
// fraction rises from 10% to 90%, scaled by 1/0.8 to the whole ramp.
double measured_penumbra(const gi::World& world, gi::Rng& rng) {
  if (world.scene.area_lights.empty()) return 0;
  double x10 = 0, x90 = 0;
  const double step = 0.002;
  for (double x = 1.2; x < 3.2; x += step) {
    const double f = visible_fraction(world, x, rng);
    if (f < 0.1) x10 = x + step;
    if (f < 0.9) x90 = x + step;
  }
  return (x90 - x10) / 0.8;
}

// 1. The penumbra against the light's size, measured on the floor of the built-in
// scene and rendered.
gi::Table penumbra_study(gi::RenderSettings settings, gi::SamplerKind sequence, const std::string& accel, gi::Rng& rng,
                         const std::function<gi::View(const gi::World&, const gi::RenderSettings&)>& view,
                         gi::Lesson& lesson) {
  gi::Table penumbra("Penumbra of the box's edge against light size (similar triangles: w = s h / (H - h))",
                     {{"light size s", 2}, {"predicted w", 3}, {"measured w", 3}, {"shadow rays/hit"}});
  std::vector<gi::Image> strip;
  for (double s : {0.0, 0.25, 0.5, 1.0, 2.0}) {
    const gi::World lit = gi::make_world(gi::soft_shadow_scene(s), gi::acceleration_from_name(accel));
    const double predicted = s * gi::soft_shadow_box_height / (gi::soft_shadow_light_height - gi::soft_shadow_box_height);
    settings.trace.soft_shadows = {gi::LightSampling::Jittered, 8};
    penumbra.add_row({s, predicted, measured_penumbra(lit, rng), s == 0 ? 1 : 64});
    strip.push_back(render_with(lit, settings, sequence, lesson).image);
    const std::string size = gi::format_number(s, 2, gi::Format::Fixed);
    lesson.picture(strip.back(), "light_size_" + size, "light of side " + size, view(lit, settings));
  }
  lesson.diagram(gi::side_by_side(strip), "penumbra_by_light_size", "light sizes 0, 0.25, 0.5, 1 and 2 side by side");
  return penumbra;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("04_soft_shadows", "Soft shadows: an area light sampled with random and jittered shadow "
                                       "rays, against a many-ray reference; penumbra against light size.");
  std::string accel = "bvh";  // a kit without lab 5 done can still render by brute force
  gi::RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.trace.max_depth = 1;
  double light_size = 1.0;
  int reference_n = 24;
  std::string sequence_option = "independent";
  std::string scene_name = "soft";  // its scene is made for the penumbra's measurement
  gi::Scene scene;
  lesson.add_image_size(settings.width, settings.height);
  lesson.options().add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names());
  lesson.add_scene(scene_name, gi::scene_names(), [&](const std::string& choice, auto& warnings) {
    scene = choice == "soft" ? gi::soft_shadow_scene(light_size)
                             : gi::load_scene(choice, warnings, lesson.scene_file_rules());
    if (scene.area_lights.empty())
      throw gi::OptionError("--scene " + choice + " has no quad light, and soft shadows need one (\"quad_lights\")");
  });
  lesson.options()
      .add("--light-size", light_size, "side of the square area light of the scene soft (scene units)", 0.05, 4.0)
      .add("--reference-n", reference_n, "reference: jittered n x n shadow rays per hit", 4, 64)
      .add("--sampler", sequence_option, "the numbers the pictures' shadow rays read (step 3 compares all three)",
           gi::sequence_option_names());
  return lesson.run(argc, argv, [&] {
    gi::Rng rng(lesson.seed(), 7);
    const gi::SamplerKind sequence = gi::sequence_from_name(sequence_option);
    const auto view = [&](const gi::World& world, const gi::RenderSettings& s) {
      return gi::View{world.scene.camera, s.width, s.height,
                      gi::describe_pixel_samples(s.sampling) + "; " + std::to_string(s.trace.soft_shadows.n) + " x " +
                          std::to_string(s.trace.soft_shadows.n) + " " +
                          gi::light_sampling_name(s.trace.soft_shadows.sampling) + " shadow rays per hit"};
    };

    // The penumbra is measured on the built-in scene's floor, where its size is known.
    const bool built_in = scene_name == "soft";
    std::optional<gi::Table> penumbra;
    if (built_in) penumbra = penumbra_study(settings, sequence, accel, rng, view, lesson);

    // 2. Shadow rays per hit against noise and time, for one light size.
    const gi::World world = gi::make_world(scene, gi::acceleration_from_name(accel));
    gi::RenderSettings reference_settings = settings;
    reference_settings.trace.soft_shadows = {gi::LightSampling::Jittered, reference_n};
    const std::uint64_t reference_seed = lesson.seed() + 1000;  // independent of the runs being measured
    const std::string scene_key = "scene " + scene.name + ", fingerprint " + gi::fingerprint(scene);
    const gi::CachedTruth cached =
        gi::cached_reference(world, reference_settings, reference_seed, lesson.threads(), scene_key, lesson.out());
    if (cached.from_cache) lesson.say("reference: read from the cache " + cached.stem.string() + ".*\n");
    else if (cached.reason != "none kept") lesson.say("reference: rendered again, " + cached.reason + "\n");
    for (const auto& file : gi::truth_files(cached.stem)) lesson.record(file, gi::OutputKind::Cache, "the cached reference");
    const gi::Image& reference = cached.truth.mean;
    lesson.picture(reference, "reference", "the reference: jittered " + std::to_string(reference_n) + "x" +
                   std::to_string(reference_n) + " shadow rays", view(world, reference_settings));

    const std::string what = built_in ? "light size " + gi::format_number(light_size, 2, gi::Format::Fixed)
                                      : "scene " + scene.name;
    gi::Table table("Shadow rays per hit, " + what + ", against jittered " + std::to_string(reference_n) + "x" +
                        std::to_string(reference_n),
                    {{"sampling"}, {"rays/hit"}, {"shadow rays"}, {"ms", 1}, {"RMSE", 2, gi::Format::Scientific},
                     {"PSNR dB", 1}});
    std::vector<gi::Series> curves;
    std::vector<gi::Image> crops;
    // The box and its shadow, enlarged 3x.
    const int cw = settings.width * 34 / 100, ch = settings.height * 31 / 100;
    const int cx = settings.width * 47 / 100, cy = settings.height * 31 / 100;
    auto crop = [&](const gi::Image& image) { return gi::enlarge(gi::crop(image, cx, cy, cw, ch), 3); };

    std::vector<gi::SoftShadowSettings> runs{{gi::LightSampling::Centre, 1}};
    for (gi::LightSampling m : {gi::LightSampling::Random, gi::LightSampling::Jittered})
      for (int n : {1, 2, 3, 4, 6, 8}) runs.push_back({m, n});
    gi::Progress progress("rendering", static_cast<long long>(runs.size()));
    for (const gi::SoftShadowSettings& run : runs) {
      settings.trace.soft_shadows = run;
      const gi::RenderResult r = render_with(world, settings, sequence, lesson);
      progress.advance();
      const std::string name = gi::light_sampling_name(run.sampling);
      const double error = gi::rmse(r.image, reference);
      table.add_row({run.sampling == gi::LightSampling::Centre ? "centre (hard)" : name, run.n * run.n,
                     r.counts.of(gi::RayKind::Shadow), 1e3 * r.seconds, error, gi::psnr(r.image, reference)});
      if (run.sampling != gi::LightSampling::Centre) {
        if (curves.empty() || curves.back().name != name) curves.push_back({name, {}, {}});
        curves.back().x.push_back(1e3 * r.seconds);
        curves.back().y.push_back(error);
      }
      if (run.n == 1 || run.n == 4) {
        const std::string label = run.sampling == gi::LightSampling::Centre ? "hard" : name + "_" + std::to_string(run.n * run.n);
        lesson.picture(r.image, label, label + " shadow rays per hit", view(world, settings));
        crops.push_back(crop(r.image));
      }
    }
    progress.finish();
    crops.push_back(crop(reference));
    lesson.diagram(gi::side_by_side(crops), "shadow_crops",
                   std::string(built_in ? "the box and its shadow" : "a window of the picture") +
                       ", 3x: hard, random 1, random 16, jittered 1, jittered 16, reference");

    if (penumbra) {
      lesson.table(*penumbra, "penumbra");
      std::cout << '\n';
    }
    lesson.table(table, "shadow_rays");
    lesson.chart({"Soft shadows: error against time", "render time (ms)", "RMSE against the reference", true, true,
                  curves},
                 "error_vs_time");

    // 3. The same random shadow rays reading three number sequences, in the penumbra.
    lesson04::sequences(world, settings, reference, lesson);
    lesson.say("\nimages and charts: " + lesson.out().string() + "/ (shadow_crops.png: hard, random 1, random 16, " +
               "jittered 1, jittered 16, reference)");
  });
}
