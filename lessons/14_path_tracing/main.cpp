// Lesson 14 -- the rendering equation, solved by Monte Carlo path tracing. First
// Monte Carlo itself (a 1-D integral, then the hemisphere, uniform against cosine
// sampling); then the Cornell box at 1, 4, 16, ... samples per pixel against a converged
// reference, with each picture's own variance; then BSDF sampling alone, light sampling
// alone and both with MIS, error against time.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/core/sampling.hpp"
#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/metrics.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"

namespace {

struct Settings {
  int width = 128, height = 128, max_spp = 128, reference_spp = 1024, threads = 0;
  std::uint64_t seed = 1;
  std::string scene = "cornell", reference;
  gi::PathSettings path;
};

// The Cornell box, square at a size that divides 256, to the default depth, is measured against
// the converged picture kept in the tree (lessons/references/), averaged down.
bool uses_stored_reference(const Settings& s) {
  return s.scene == "cornell" && s.width == s.height && 256 % s.width == 0 &&
         s.path.max_depth == gi::PathSettings{}.max_depth;
}

gi::View view(const gi::PathScene& scene, int width, int height, int spp) {
  return {scene.scene().camera, width, height,
          std::to_string(spp) + " paths per pixel through uniform random points of it (box filter)"};
}

// 1. Monte Carlo before it renders anything. RMS error of 400 estimates at each N of
//    int_0^pi sin x dx = 2 (uniform x), and of the irradiance under a sky of radiance
//    L(theta) = 1 + 3 cos^2(theta), E = int L cos dw = 2.5 pi, drawing directions
//    uniformly (p = 1 / 2 pi) or by the cosine (p = cos / pi).
void monte_carlo_warm_up(const Settings& s, gi::Lesson& lesson) {
  gi::Table table("Monte Carlo: RMS error of 400 estimates with N samples (closed forms: 2 and 2.5 pi)",
                  {{"N"},
                   {"1-D, uniform", 2, gi::Format::Scientific},
                   {"sky, uniform", 2, gi::Format::Scientific},
                   {"sky, cosine", 2, gi::Format::Scientific}});
  gi::Rng rng(s.seed, 14);
  const auto sky = [](const gi::vec3& w) { return 1 + 3 * w.z * w.z; };
  for (int n = 1; n <= 4096; n *= 4) {
    double e1 = 0, e2 = 0, e3 = 0;
    for (int trial = 0; trial < 400; ++trial) {
      double line = 0, uniform = 0, cosine = 0;
      for (int k = 0; k < n; ++k) {
        line += std::sin(gi::pi * rng.uniform()) * gi::pi;  // f(x) / p(x), p = 1 / pi
        const gi::vec3 u = gi::sample_uniform_hemisphere({rng.uniform(), rng.uniform()});
        uniform += sky(u) * u.z / gi::uniform_hemisphere_pdf();
        const gi::vec3 c = gi::sample_cosine_hemisphere({rng.uniform(), rng.uniform()});
        cosine += sky(c) * c.z / gi::cosine_hemisphere_pdf(c.z);
      }
      e1 += std::pow(line / n - 2, 2), e2 += std::pow(uniform / n - 2.5 * gi::pi, 2);
      e3 += std::pow(cosine / n - 2.5 * gi::pi, 2);
    }
    table.add_row({n, std::sqrt(e1 / 400), std::sqrt(e2 / 400), std::sqrt(e3 / 400)});
  }
  lesson.table(table, "monte_carlo");
}

// Any other scene or size: a reference rendered here once and kept in the output folder
// (render/truth.hpp), reused while the scene, the sample count and the path tracer's
// code are the same.
gi::Truth own_reference(const gi::PathScene& scene, const Settings& s, gi::Lesson& lesson) {
  const std::string stem = "reference_" + s.scene + "_" + std::to_string(s.width) + "x" + std::to_string(s.height) +
                           "_depth" + std::to_string(s.path.max_depth);
  gi::TruthKey key = gi::path_truth_key(scene, s.path, s.width, s.height, gi::path_code_fingerprint());
  key.fingerprint += " spp " + std::to_string(s.reference_spp);
  const std::uint64_t seed = s.seed + 1000000;  // streams no picture measured uses
  const gi::CachedTruth cached = gi::cached_truth(lesson.out() / stem, key, seed, [&](const std::string& why) {
    lesson.say("rendering a reference: " + std::to_string(s.reference_spp) + " spp (" + why + ")");
    gi::Film film = gi::make_film(s.width, s.height, seed);
    gi::Progress progress("reference", s.reference_spp);
    for (int done = 0; done < s.reference_spp; done += 16) {
      gi::path_trace(film, scene, s.path, std::min(16, s.reference_spp - done), s.threads);
      progress.advance(std::min(16, s.reference_spp - done));
    }
    progress.finish();
    return film;
  }, gi::path_truth_about(s.scene, s.path));
  if (cached.from_cache) lesson.say("reference: read from " + cached.stem.string() + ".*, kept by an earlier run");
  for (const auto& file : gi::truth_files(cached.stem))
    lesson.record(file, gi::OutputKind::Cache, "the reference kept for later runs");
  return cached.truth;
}

double grey(const gi::Pixel& p) { return (double(p.x) + p.y + p.z) / 3; }

double mean_of(const gi::Image& image) {
  double sum = 0;
  for (const gi::Pixel& p : image.pixels) sum += grey(p);
  return sum / double(image.pixels.size());
}

// One strategy, sample after sample: snapshots at 1, 2, 4, ... spp with the time so far.
struct Snapshot {
  int spp;
  double seconds, rmse, relative, variance;
};

std::vector<Snapshot> converge(const gi::PathScene& scene, const Settings& s, gi::Strategy strategy,
                               const gi::Truth& reference, gi::Lesson* pictures) {
  gi::PathSettings path = s.path;
  path.strategy = strategy;
  gi::Film film = gi::make_film(s.width, s.height, s.seed);
  std::vector<Snapshot> snapshots;
  std::vector<gi::Image> strip;  // the pictures at 1, 4, 16, ... spp, then the reference
  gi::Progress progress(gi::name(strategy), s.max_spp);
  double seconds = 0;
  for (int spp = 1; spp <= s.max_spp; spp *= 2) {
    const gi::Timer timer;
    gi::path_trace(film, scene, path, spp - static_cast<int>(film.samples), s.threads);
    seconds += timer.seconds();
    progress.advance(spp / 2 + (spp == 1));
    const gi::Image picture = gi::film_mean(film);
    snapshots.push_back({spp, seconds, gi::rmse(picture, reference.mean),
                         gi::relative_rms_error(picture, reference.mean), mean_of(gi::film_variance(film))});
    const bool power_of_four = (spp & 0x55555555) != 0;
    if (pictures && power_of_four) {
      pictures->picture(picture, s.scene + "_" + std::to_string(spp) + "spp",
                        s.scene + ", " + gi::name(strategy) + ", " + std::to_string(spp) + " spp",
                        view(scene, s.width, s.height, spp));
      strip.push_back(picture);
    }
  }
  progress.finish();
  if (film.discarded && pictures)
    pictures->say(gi::name(strategy) + ": " + std::to_string(film.discarded) + " samples not finite, counted as 0");
  if (pictures) {
    // Where the noise is: each pixel's relative standard error, sqrt(variance) / mean.
    const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
    std::vector<double> relative;
    for (std::size_t i = 0; i < mean.pixels.size(); ++i)
      relative.push_back(std::sqrt(grey(variance.pixels[i])) / std::max(1e-6, grey(mean.pixels[i])));
    pictures->diagram(gi::false_colour(relative, s.width, s.height, 0, 0.5),
                      "relative_error_" + std::to_string(s.max_spp) + "spp",
                      "each pixel's relative standard error at the last picture, black 0 to red 50%",
                      gi::ColourScale{0, 0.5, "relative standard error of the pixel's mean"});
    strip.push_back(reference.mean);
    pictures->diagram(gi::side_by_side(strip), "progression", "1, 4, 16, ... spp, then the reference");
    pictures->picture(reference.mean, "reference", "the reference, " + std::to_string(reference.spp) + " spp",
                      view(scene, s.width, s.height, static_cast<int>(reference.spp)));
  }
  return snapshots;
}

// The pictures' table: MIS from 1 spp on, its error against the reference and the
// error its own variance predicts, sqrt(mean variance + the reference's).
void picture_table(const std::vector<Snapshot>& mis, const gi::Truth& reference, const Settings& s,
                   gi::Lesson& lesson) {
  gi::Table table("Path tracing (MIS), " + std::to_string(s.width) + "x" + std::to_string(s.height) +
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

// The white furnace (a closed box, every wall rho = 0.5 emitting L_e = 1): its exact
// picture is L_e (1 + rho + ... + rho^D) everywhere, an independent reference.
gi::Truth furnace_truth(const Settings& s) {
  double L = 0;
  for (int k = 0; k <= s.path.max_depth; ++k) L += std::pow(0.5, k);
  gi::Truth exact;
  exact.mean = gi::Image(s.width, s.height, gi::Pixel(float(L)));
  exact.standard_error = gi::Image(s.width, s.height);
  return exact;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("14_path_tracing", "Path tracing the rendering equation: Monte Carlo, pictures at 1 to "
                                       "4096 samples per pixel against a converged reference, and BSDF "
                                       "sampling, light sampling and MIS, error against time.");
  Settings s;
  s.reference = std::string(GI_SOURCE_DIR) + "/lessons/references/cornell_256x256";
  lesson.add_image_size(s.width, s.height);
  lesson.options()
      .add("--scene", s.scene, "scene to render", gi::path_scene_names())
      .add("--max-spp", s.max_spp, "the last picture's samples per pixel (1, 2, 4, ... up to it)", 1, 1 << 16)
      .add("--max-depth", s.path.max_depth, "bounces per path", 0, 10000)
      .add("--reference", s.reference, "the Cornell box's converged picture (files STEM.txt, STEM.pfm, ...)")
      .add("--reference-spp", s.reference_spp, "samples per pixel of a reference this lesson renders itself", 16,
           1 << 20);
  std::optional<gi::PathScene> scene;
  std::optional<gi::Truth> reference;
  lesson.add_check([&] {  // before any work: a missing, damaged or stale reference is said at once
    scene.emplace(gi::make_path_scene(gi::make_path_scene_by_name(s.scene)));
    if (uses_stored_reference(s)) reference = gi::stored_truth_at(s.reference, "cornell", 256, s.width, s.height);
  });
  return lesson.run(argc, argv, [&] {
    s.threads = lesson.threads();
    s.seed = lesson.seed();

    // 1. Monte Carlo, before it renders anything.
    monte_carlo_warm_up(s, lesson);

    // 2. The pictures, MIS at 1, 2, 4, ... spp, against the reference.
    const gi::Camera& camera = scene->scene().camera;
    const auto point = [](const gi::vec3& p) {
      return "(" + gi::format_number(p.x, 1, gi::Format::Fixed) + ", " + gi::format_number(p.y, 1, gi::Format::Fixed) +
             ", " + gi::format_number(p.z, 1, gi::Format::Fixed) + ")";
    };
    lesson.say("\ncamera: eye " + point(camera.eye) + ", looking at " + point(camera.look_at) + ", up " +
               point(camera.up) + ", vertical field of view " +
               gi::format_number(camera.vertical_fov, 4, gi::Format::Fixed) +
               " degrees; square pixels, each the mean over its area (a box filter)");
    if (!reference) reference = own_reference(*scene, s, lesson);
    lesson.say("reference: " + reference->about_value("scene") + ", " + std::to_string(reference->spp) + " spp (" +
               reference->about_value("strategy") + ", seed " + std::to_string(reference->seed) + ") at " +
               std::to_string(s.width) + "x" + std::to_string(s.height) + "; its own relative standard error " +
               gi::format_number(100 * gi::relative_standard_error(reference->standard_error, reference->mean), 2,
                                 gi::Format::Fixed) +
               "% per pixel\n");
    std::vector<std::vector<Snapshot>> runs;
    for (const gi::Strategy strategy : {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis})
      runs.push_back(converge(*scene, s, strategy, *reference, strategy == gi::Strategy::Mis ? &lesson : nullptr));
    picture_table(runs.back(), *reference, s, lesson);

    // 3. The three strategies: on this scene, and on the white furnace, whose lights are
    // as large as can be -- where BSDF sampling wins and MIS must follow it.
    // Its picture is the same everywhere, so a small one tells as much.
    const gi::PathScene furnace = gi::make_path_scene(gi::furnace_scene(0.5, 1.0));
    Settings small = s;
    small.width = small.height = 32;
    std::vector<std::vector<Snapshot>> furnace_runs;
    for (const gi::Strategy strategy : {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis})
      furnace_runs.push_back(converge(furnace, small, strategy, furnace_truth(small), nullptr));
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

    // 4. Speed, in the unit docs/15 compares with Blender's Cycles on the same box:
    // ms per sample per pixel at 256x256.
    const double rate = mis.back().spp * double(s.width) * s.height / mis.back().seconds;
    lesson.say("\nspeed: " + gi::format_number(1e-6 * rate, 2, gi::Format::Fixed) + " M samples/s with MIS = " +
               gi::format_number(1e3 * 256 * 256 / rate, 1, gi::Format::Fixed) +
               " ms per sample per pixel at 256x256, on " + (s.threads ? std::to_string(s.threads) : "all") +
               " threads (against Blender's Cycles: docs/15, \"Speed\")");
    lesson.say("images: " + lesson.out().string() + "/ (" + s.scene + "_<spp>spp.png and .pfm, progression.png: 1, " +
               "4, 16 ... spp and the reference; relative_error_" + std::to_string(s.max_spp) +
               "spp.png, error_vs_time.svg)");
  });
}
