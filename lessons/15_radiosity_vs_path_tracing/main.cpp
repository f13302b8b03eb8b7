// Lesson 15 -- radiosity measured against path tracing. The Cornell box by every
// radiosity method of the course and by path tracing, all scored against the stored
// converged picture on one chart of error against time; what path tracing needs to match
// each radiosity recipe; crops of where each fails, side by side; and what radiosity
// cannot draw at all (a mirror, a caustic) and path tracing draws slowly.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/pathtrace/convergence.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/recipe_picture.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"

namespace {

struct Settings {
  int size = 128, max_spp = 32, caustic_spp = 64, threads = 0;
  bool full = false;
  std::uint64_t seed = 1;
  std::string reference;
};

// One point of the chart: a method's picture, its error against the truth and its time.
struct Run {
  std::string family, name;
  int elements = 0;  // 0: path tracing
  double seconds = 0;
  double error = 0;        // relative RMS over the interior blocks (picture_error.hpp)
  double pixel_error = 0;  // the same over single interior pixels: what the eye sees of noise
  gi::Image picture;
};

// The two masks a picture is scored over: blocks (the course's measure, lesson 12's) and
// single pixels, with the reference's own error by each.
struct Scoring {
  gi::BlockMask blocks, pixels;
  double noise = 0, pixel_noise = 0;
};

void score(Run& run, const gi::Truth& truth, const Scoring& scoring) {
  run.error = gi::picture_error(run.picture, truth.mean, scoring.blocks).relative_rms;
  run.pixel_error = gi::picture_error(run.picture, truth.mean, scoring.pixels).relative_rms;
}

// The radiosity recipes: uniform meshes of about `elements` elements; time from the
// scene to the picture (mesh, form factors, direct light, solver, display), as path
// tracing's is.
struct Method {
  std::string family;
  std::vector<int> elements;
  gi::Recipe recipe;
  bool direct_per_pixel = false;
};

std::vector<Method> radiosity_methods(bool full) {
  gi::Recipe all_light;  // lessons 08-11: the hemicube at resolution 100 carries all the light
  all_light.exact_direct = false;
  gi::Recipe monte_carlo_all = all_light, exact_mc, shooting, per_pixel, per_pixel_hemicube;
  monte_carlo_all.form_factors.method = exact_mc.form_factors.method = per_pixel.form_factors.method =
      gi::FormFactorMethod::MonteCarlo;
  monte_carlo_all.form_factors.rays = exact_mc.form_factors.rays = per_pixel.form_factors.rays = 256;
  shooting.solver = gi::RecipeSolver::Progressive;
  shooting.elements_per_side = 3;  // shoot from patches, receive at 3 x 3 elements each
  shooting.form_factors.hemicube_resolution = per_pixel_hemicube.form_factors.hemicube_resolution = 0;  // from the mesh
  per_pixel.direct.light_cells = per_pixel_hemicube.direct.light_cells = 4;  // 2 x 2 eye rays average the rest
  const auto sizes = [&](std::vector<int> quick, std::vector<int> more) {
    if (full) quick.insert(quick.end(), more.begin(), more.end());
    return quick;
  };
  std::vector<Method> list = {
      {"hemicube 100, all light, Gauss-Seidel", sizes({150, 300}, {600, 1200, 2400}), all_light},
      {"Monte Carlo 256, all light, Gauss-Seidel", sizes({300}, {1200}), monte_carlo_all},
      {"exact direct + Monte Carlo, Gauss-Seidel", sizes({300}, {1200, 2400}), exact_mc},
      {"exact direct + hemicube, progressive 3x3", sizes({900}, {2700, 8100}), shooting},
      {"direct per pixel + Monte Carlo, Gauss-Seidel", sizes({150, 300}, {600, 1200, 2400}), per_pixel, true},
      {"direct per pixel + hemicube, Gauss-Seidel", sizes({}, {600, 1200}), per_pixel_hemicube, true},
  };
  // Lesson 13's hierarchical radiosity: no uniform mesh (the elements are its leaves),
  // BF_eps 3e-3 at lesson 13's min area 3e-4, the direct light per pixel as above.
  gi::Recipe hierarchical = per_pixel;
  hierarchical.solver = gi::RecipeSolver::Hierarchical;
  hierarchical.hierarchical.refinement.threshold = 3e-3;
  hierarchical.hierarchical.refinement.min_area = 3e-4;
  list.push_back({"direct per pixel + hierarchical, BF_eps 3e-3", {0}, hierarchical, true});
  return list;
}

std::vector<Run> solve_radiosity(const gi::RadiosityScene& scene, const Settings& s, const gi::Truth& truth,
                                 const Scoring& scoring) {
  gi::DisplaySettings display;
  display.width = display.height = s.size;
  std::vector<Run> runs;
  for (Method m : radiosity_methods(s.full))
    for (int elements : m.elements) {
      m.recipe.elements = elements;
      const gi::Timer timer;
      const gi::RecipeResult r = gi::solve_recipe(scene.surfaces, m.recipe, s.threads);
      if (r.status != gi::SolveStatus::Converged)
        throw std::runtime_error(m.family + " at " + std::to_string(elements) + " elements did not converge");
      Run run{m.family, m.family, static_cast<int>(r.mesh.elements.size()), 0, 0, 0, {}};
      run.picture = gi::recipe_picture(r, scene.camera, display, m.direct_per_pixel, m.recipe.direct, s.seed, s.threads);
      run.seconds = timer.seconds();
      score(run, truth, scoring);
      runs.push_back(std::move(run));
    }
  return runs;
}

// Path tracing (MIS) at 1, 2, 4, ... spp, one film sampled further for each picture.
std::vector<Run> path_trace(const gi::PathScene& scene, const Settings& s, const gi::Truth& truth,
                            const Scoring& scoring) {
  gi::Film film = gi::make_film(s.size, s.size, s.seed);
  gi::Progress progress("path tracing", s.max_spp);
  std::vector<Run> runs;
  double seconds = 0;
  for (int spp = 1; spp <= s.max_spp; spp *= 2) {
    const gi::Timer timer;
    gi::path_trace(film, scene, {}, spp - static_cast<int>(film.samples), s.threads);
    seconds += timer.seconds();
    progress.advance(spp / 2 + (spp == 1));
    Run run{"path tracing (MIS)", "path tracing (MIS), " + std::to_string(spp) + " spp", 0, seconds, 0, 0, {}};
    run.picture = gi::film_mean(film);
    score(run, truth, scoring);
    runs.push_back(std::move(run));
  }
  progress.finish();
  return runs;
}

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

// A crop of each picture, side by side, enlarged: (x, y, w) as fractions of the picture.
void crops(const std::vector<const gi::Image*>& pictures, double fx, double fy, double fw, const std::string& stem,
           const std::string& caption, gi::Lesson& lesson) {
  const int size = pictures.front()->width, w = std::max(8, static_cast<int>(fw * size));
  std::vector<gi::Image> strip;
  for (const gi::Image* p : pictures)
    strip.push_back(gi::enlarge(gi::crop(*p, static_cast<int>(fx * size), static_cast<int>(fy * size), w, w),
                                std::max(1, 384 / w)));
  lesson.diagram(gi::side_by_side(strip), stem, caption, 2);
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

// 3. What radiosity cannot draw: the box with a mirror ball and a glass ball. Path
// tracing draws it, slowly where light comes by L S+ D paths: the caustic under the
// glass ball. Each region's noise is its pixels' mean relative standard error, from
// the film's own variance (no reference needed).
void specular(const Settings& s, gi::Lesson& lesson) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell-spheres"));
  gi::Film film = gi::make_film(s.size, s.size, s.seed);
  gi::Progress progress("mirror and glass", s.caustic_spp);
  std::vector<gi::Image> pictures;
  gi::Table table("The box with a mirror ball and a glass ball, path traced: noise where the light comes by a "
                  "caustic against a wall lit directly",
                  {{"spp"}, {"time s", 2}, {"caustic: rel. std. error %", 1}, {"back wall: rel. std. error %", 1},
                   {"ratio"}});
  const gi::Timer timer;
  for (int spp = s.caustic_spp / 16; spp <= s.caustic_spp; spp *= 4) {
    const int more = spp - static_cast<int>(film.samples);
    gi::path_trace(film, scene, {}, more, s.threads);
    progress.advance(more);
    const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
    // Mean relative standard error over a square of pixels (fractions of the picture).
    const auto noise = [&](double fx, double fy, double fw) {
      const int x0 = static_cast<int>(fx * s.size), y0 = static_cast<int>(fy * s.size), w = static_cast<int>(fw * s.size);
      double sum = 0;
      for (int y = y0; y < y0 + w; ++y)
        for (int x = x0; x < x0 + w; ++x) {
          const gi::Pixel m = mean.at(x, y), v = variance.at(x, y);
          sum += std::sqrt((v.x + v.y + v.z) / 3) / std::max(1e-6, (m.x + m.y + m.z) / 3.0);
        }
      return sum / (w * w);
    };
    const double caustic = noise(0.62, 0.88, 0.08), wall = noise(0.46, 0.20, 0.08);
    table.add_row({spp, timer.seconds(), 100 * caustic, 100 * wall, caustic / wall});
    pictures.push_back(mean);
  }
  progress.finish();
  lesson.table(table, "caustic_noise");
  lesson.say("to be as clean as the wall, the caustic needs (ratio)^2 times the samples: noise falls as 1/sqrt(spp)");
  const gi::View view{scene.scene().camera, s.size, s.size,
                      std::to_string(s.caustic_spp) + " paths per pixel through uniform random points of it (box filter)"};
  lesson.picture(pictures.back(), "mirror_and_glass", "cornell-spheres, path traced, " + std::to_string(s.caustic_spp) +
                                                          " spp: the mirror and the caustic radiosity cannot draw",
                 view, 1);
  std::vector<const gi::Image*> strip;
  for (const gi::Image& p : pictures) strip.push_back(&p);
  crops(strip, 0.5, 0.6, 0.38, "crop_caustic",
        "the floor under the glass ball at " + std::to_string(s.caustic_spp / 16) + ", " +
            std::to_string(s.caustic_spp / 4) + " and " + std::to_string(s.caustic_spp) + " spp",
        lesson);
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
    const std::vector<Run> radiosity = solve_radiosity(box, s, *truth, scoring);
    const std::vector<Run> paths = path_trace(*scene, s, *truth, scoring);
    chart_and_table(radiosity, paths, *truth, scoring, s, lesson);

    // 2. Where each fails, side by side.
    std::cout << '\n';
    where_each_fails(radiosity, paths, *truth, view, lesson);

    // 3. What radiosity cannot draw, and path tracing draws slowly.
    std::cout << '\n';
    specular(s, lesson);
    lesson.say("\nimages, tables and the chart: " + lesson.out().string() + "/");
  });
}
