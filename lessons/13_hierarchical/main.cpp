// Lesson 13 -- hierarchical radiosity: keep every surface whole and cut it only where a
// link between two pieces needs it (Hanrahan, Salzman and Aupperle 1991). The Cornell
// box at several thresholds with the leaves drawn over the shading, every picture
// scored against the path-traced truth; links against leaves beside the n^2 of a
// uniform mesh; error against time beside uniform meshes; where it fails; and what can
// change without new links: the light and the camera.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/direct_display.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/hierarchical/link_gather.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"
#include "gi/viewer/hierarchical.hpp"
#include "gi/report/lesson.hpp"

namespace {

// Every picture is the published camera's at the stored truth's size, scored against
// the converged path-traced picture of the same box (lessons/references/, made by
// 14_make_reference): relative RMS over the 8 x 8 blocks that lie on one surface other
// than the light (picture_error.hpp), as lesson 12 scores every uniform method.
struct Setup {
  gi::RadiosityScene scene;
  gi::HierarchicalSettings settings;  // exact direct light on: the lesson's default method
  gi::DisplaySettings display;
  gi::DirectLightSettings per_pixel;  // the direct light drawn per pixel (lesson 12's split)
  // That light depends on the surfaces, not on how they are meshed: cast on the
  // surfaces themselves, its time counted in every picture that shows it.
  const gi::DirectRadiance* direct = nullptr;
  gi::Image truth;
  gi::BlockMask mask;
  double exposure = 1.5;
  int threads = 0;
  std::uint64_t seed = 1;  // the display's films
  int uniform_elements = 1000;  // the finest uniform mesh of the comparison; also a quarter of it
};

// How a hierarchical solution is shown: all its light on the leaves (Gouraud, no
// cracks), or lesson 12's split -- the exact direct light at every eye ray, and only
// what has bounced more than once, B - E - D, from the leaves -- or the same split with
// B - E - D gathered over the links at the leaves' corners (the final gather,
// link_gather.hpp).
enum class Shown { Leaves, DirectPerPixel, Gathered };

struct Scored {
  gi::Image picture;
  double seconds = 0;  // the per-pixel direct light's: part of the answer, so it counts
  double error = 0;    // relative RMS against the truth
};

Scored score(const Setup& s, const gi::HierarchicalRun& run, Shown shown) {
  Scored out;
  const gi::Timer timer;
  const gi::LeafMesh leaves = gi::leaf_mesh(run.hierarchy);
  const gi::FormFactorScene elements(gi::element_shapes(leaves.mesh));
  const std::vector<gi::Color> B = gi::shown_radiosity(run);
  if (shown == Shown::Leaves) {
    out.picture = gi::render_radiosity_picture(elements, leaves.mesh, B, gi::leaf_vertex_radiosity(leaves, B),
                                               s.scene.camera, s.display, s.seed, s.threads)
                      .radiance;
  } else {
    const std::vector<gi::Color> rest = gi::indirect_part(leaves.mesh, B, run.result.direct);
    const std::vector<gi::Color> at_vertices = shown == Shown::Gathered
                                                   ? gi::gathered_at_vertices(run.hierarchy, leaves, s.threads)
                                                   : gi::leaf_vertex_radiosity(leaves, rest);
    const gi::MeshRadiance bounced{elements, leaves.mesh, rest, at_vertices, gi::Shading::Smooth};
    out.picture = gi::render_display(gi::sum_of(*s.direct, bounced), s.scene.camera, s.display, s.seed, s.threads)
                      .radiance;
    out.seconds = timer.seconds();
  }
  out.error = gi::picture_error(out.picture, s.truth, s.mask).relative_rms;
  return out;
}

gi::HierarchicalSettings with(gi::HierarchicalSettings s, double bf_eps, bool exact_direct) {
  s.refinement.threshold = bf_eps;
  s.exact_direct = exact_direct;
  return s;
}

std::string percent(double x) { return gi::format_number(100 * x, 2, gi::Format::Fixed); }

// 1. Thresholds, for HSA's algorithm as published (all light over the links) and with
// the direct light exact: leaves, links, memory, time and error; the leaves drawn.
void thresholds(const Setup& s, gi::Chart& chart, gi::Lesson& lesson) {
  gi::Table table("Hierarchical radiosity on the Cornell box against the path-traced truth (relative RMS, " +
                      std::to_string(s.mask.count()) + " interior 8x8 blocks)",
                  {{"BF_eps", 0, gi::Format::Scientific}, {"light"}, {"leaves"}, {"links"}, {"links / leaf", 1},
                   {"link MB", 2}, {"s", 2}, {"error %", 2}});
  gi::Series links{"hierarchical: links", {}, {}}, square{"uniform mesh: n^2 form factors", {}, {}};
  gi::Series all{"hierarchical, all light by links", {}, {}}, exact{"hierarchical, exact direct", {}, {}},
      pixel{"hierarchical, direct per pixel", {}, {}}, gathered{"hierarchical, direct per pixel, final gather", {}, {}};
  std::vector<gi::Image> shown;
  for (const double eps : {1e-2, 3e-3, 1e-3, 3e-4}) {
    for (const bool exact_direct : {false, true}) {
      // BF_eps 1e-3 and coarser with exact direct light: the defaults stay within a
      // lecture's breath; 12_cornell_bench --threshold 3e-4 --min-area 3e-4 for the next.
      if (exact_direct && eps < 1e-3) continue;
      const gi::HierarchicalRun run = gi::run_hierarchical(s.scene, with(s.settings, eps, exact_direct), s.threads);
      const double leaves = run.result.rounds.back().leaves, n_links = static_cast<double>(gi::link_count(run.hierarchy));
      const auto row = [&](const std::string& light, const Scored& scored, gi::Series& series) {
        const double seconds = run.seconds + scored.seconds;
        table.add_row({eps, light, static_cast<int>(leaves), static_cast<long long>(n_links), n_links / leaves,
                       run.link_bytes / 1e6, seconds, 100 * scored.error});
        series.x.push_back(seconds), series.y.push_back(100 * scored.error);
      };
      if (!exact_direct) {
        row("all by links", score(s, run, Shown::Leaves), all);
        links.x.push_back(leaves), links.y.push_back(n_links);
        square.x.push_back(leaves), square.y.push_back(leaves * (leaves - 1));
        gi::DisplaySettings large = s.display;  // room for the leaves' outlines
        large.width = large.height = 384;
        shown.push_back(gi::render_leaves(run, s.scene.camera, large, s.seed, s.threads).with_mesh);
        continue;
      }
      row("exact direct", score(s, run, Shown::Leaves), exact);
      const Scored means = score(s, run, Shown::DirectPerPixel);
      row("direct per pixel", means, pixel);
      const Scored final_gather = score(s, run, Shown::Gathered);
      row("final gather", final_gather, gathered);
      if (eps != s.settings.refinement.threshold) continue;
      // The tall block's foot, where a face sees the floor at its feet: enlarged 4x.
      const int x0 = 36, y0 = 150, w = 96;
      std::vector<gi::Image> strip;
      for (const gi::Image* p : {&means.picture, &final_gather.picture, &s.truth})
        strip.push_back(gi::enlarge(gi::crop(*p, x0, y0, w, w), 4));
      lesson.diagram(gi::side_by_side(strip), "final_gather", "the tall block's foot: what bounced from the leaves' "
                     "means, gathered over the links at their corners, the path-traced truth", s.exposure);
      lesson.picture(final_gather.picture, "hierarchical",
                     "exact direct light per pixel, the rest gathered over the links at the leaves' corners",
                     {s.scene.camera, s.display.width, s.display.height, gi::describe_pixel_samples(s.display)},
                     s.exposure);
      const gi::LeafMesh mesh = gi::leaf_mesh(run.hierarchy);
      const std::vector<gi::Color> B = gi::shown_radiosity(run);
      lesson.file("leaves.ply", gi::OutputKind::Mesh, "the leaves at the lesson's BF_eps, exact direct light, vertex "
                  "colours, T-vertices in the faces",
                  [&](const std::filesystem::path& file) {
                    gi::write_ply(mesh.mesh, gi::leaf_vertex_radiosity(mesh, B), s.exposure, file, mesh.faces);
                  });
      lesson.viewer("the leaves at the lesson's BF_eps: pick one to see the links that bring it light",
                    [&](const std::filesystem::path& file) {
                      gi::write_viewer_data(gi::hierarchical_viewer_data(lesson.name(), "Hierarchical radiosity: "
                                                                         "the leaves and the links that light them",
                                                                         run, s.scene.camera, s.exposure),
                                            file);
                    });
      gi::Table rounds("Rounds at BF_eps " + gi::format_number(eps, 0, gi::Format::Scientific) +
                           ", exact direct light (round 0: F-refinement)",
                       {{"round"}, {"nodes"}, {"leaves"}, {"links"}, {"judged"}, {"replaced"}, {"iterations"},
                        {"refine ms", 0}, {"solve ms", 0}, {"change in B", 1, gi::Format::Scientific}});
      for (const gi::RefinementRound& r : run.result.rounds)
        rounds.add_row({r.round, r.nodes, r.leaves, static_cast<long long>(r.links), static_cast<long long>(r.evaluated),
                        static_cast<long long>(r.replaced), r.iterations, 1e3 * r.refine_seconds, 1e3 * r.solve_seconds,
                        r.change});
      lesson.table(rounds, "rounds");
      lesson.say(gi::describe(run.result.balanced));
    }
  }
  lesson.table(table, "thresholds");
  lesson.diagram(gi::side_by_side(shown), "leaves", "the leaves at BF_eps 1e-2, 3e-3, 1e-3 and 3e-4, all light by links",
                 1);
  lesson.chart({"Links against leaves: hierarchical beside a uniform mesh", "leaves (elements)", "links (form factors)",
                true, true, {links, square}},
               "links");
  chart.series.push_back(all), chart.series.push_back(exact), chart.series.push_back(pixel);
  chart.series.push_back(gathered);
}

// 2. Uniform meshes as lesson 12 seats them (exact direct light, hemicube sized to the
// mesh, Gauss-Seidel), shown both ways: error against whole time, mesh to B.
void uniform_meshes(const Setup& s, gi::Chart& chart, gi::Lesson& lesson) {
  gi::Table table("Uniform meshes, exact direct + hemicube, Gauss-Seidel to 1e-5; against the same truth",
                  {{"elements"}, {"light"}, {"s", 2}, {"error %", 2}});
  gi::Series exact{"uniform, exact direct", {}, {}}, pixel{"uniform, direct per pixel", {}, {}};
  for (const int elements : {s.uniform_elements / 4, s.uniform_elements}) {
    gi::Recipe recipe;
    recipe.elements = elements;
    recipe.form_factors.hemicube_resolution = 0;  // from the mesh
    const gi::RecipeResult r = gi::solve_recipe(s.scene.surfaces, recipe, s.threads);
    const gi::FormFactorScene shapes(gi::element_shapes(r.mesh));
    const gi::Image mesh_picture =
        gi::render_radiosity_picture(shapes, r.mesh, r.B, s.scene.camera, s.display, s.seed, s.threads).radiance;
    const gi::Timer timer;
    const std::vector<gi::Color> rest = gi::indirect_part(r.mesh, r.B, r.direct), at_vertices = gi::vertex_radiosity(r.mesh, rest);
    const gi::MeshRadiance bounced{shapes, r.mesh, rest, at_vertices, gi::Shading::Smooth};
    const gi::Image picture =
        gi::render_display(gi::sum_of(*s.direct, bounced), s.scene.camera, s.display, s.seed, s.threads).radiance;
    const double per_pixel = timer.seconds();
    const int n = static_cast<int>(r.mesh.elements.size());
    const double e_mesh = gi::picture_error(mesh_picture, s.truth, s.mask).relative_rms;
    const double e_pixel = gi::picture_error(picture, s.truth, s.mask).relative_rms;
    table.add_row({n, "exact direct", r.seconds(), 100 * e_mesh});
    table.add_row({n, "direct per pixel", r.seconds() + per_pixel, 100 * e_pixel});
    exact.x.push_back(r.seconds()), exact.y.push_back(100 * e_mesh);
    pixel.x.push_back(r.seconds() + per_pixel), pixel.y.push_back(100 * e_pixel);
  }
  lesson.table(table, "uniform");
  chart.series.push_back(exact), chart.series.push_back(pixel);
}

// 3. Where it fails, one row each, against the same truth: thresholds so loose that
// nothing is split, and a minimum area too large to resolve the shadows (all light by
// links: the shadows are then the links' business).
void stability(const Setup& s, gi::Lesson& lesson) {
  gi::HierarchicalSettings loose = with(s.settings, 1, false), coarse = with(s.settings, s.settings.refinement.threshold, false);
  loose.refinement.form_factor_threshold = 2;
  coarse.refinement.min_area = 1e-2;
  const std::vector<std::pair<std::string, gi::HierarchicalSettings>> cases = {
      {"thresholds so loose nothing is split", loose}, {"minimum area 1e-2: the shadows unresolved", coarse}};
  gi::Table table("Where hierarchical radiosity goes wrong, all light by links, against the truth",
                  {{"case"}, {"leaves"}, {"links"}, {"s", 2}, {"error %", 2}});
  std::vector<gi::Image> shown;
  for (const auto& [what, settings] : cases) {
    const gi::HierarchicalRun run = gi::run_hierarchical(s.scene, settings, s.threads);
    table.add_row({what, run.result.rounds.back().leaves, static_cast<long long>(gi::link_count(run.hierarchy)),
                   run.seconds, 100 * score(s, run, Shown::Leaves).error});
    shown.push_back(gi::render_leaves(run, s.scene.camera, s.display, s.seed, s.threads).with_mesh);
  }
  lesson.table(table, "stability");
  lesson.diagram(gi::side_by_side(shown), "stability", "the cases of the stability table, leaves drawn", 1);
}

// 4. What can change: a new light on the same links (re-solve only) against a full
// recompute; a dimmer is a product (the system is linear in E); a new camera is a new
// picture only. All light by links here: the links then carry the light itself.
void what_can_change(const Setup& s, gi::Lesson& lesson) {
  const gi::HierarchicalSettings settings = with(s.settings, s.settings.refinement.threshold, false);
  gi::HierarchicalRun run = gi::run_hierarchical(s.scene, settings, s.threads);
  const double first = run.seconds;
  std::vector<gi::Color> warm;
  for (const gi::Surface& surface : s.scene.surfaces) warm.push_back(gi::Color(0.5, 0.3, 0.1) * surface.emission);
  const gi::Timer resolve_timer;
  gi::relight(run, warm, settings.tolerance, s.threads);
  const double resolve = resolve_timer.seconds();
  gi::DisplaySettings shown = s.display;
  shown.white = 1 / s.exposure;
  const gi::Image relit_shown = gi::render_leaves(run, s.scene.camera, shown, s.seed, s.threads).picture.shown;
  gi::RadiosityScene warm_scene = s.scene;
  for (std::size_t k = 0; k < warm.size(); ++k) warm_scene.surfaces[k].emission = warm[k];
  const gi::HierarchicalRun fresh = gi::run_hierarchical(warm_scene, settings, s.threads);
  const gi::Image a = score(s, run, Shown::Leaves).picture, b = score(s, fresh, Shown::Leaves).picture;
  // The dimmer: 0.3 x the light, solved, against 0.3 x the solution.
  const gi::SolverResult relit = gi::relight(run, warm, 1e-10, s.threads);
  std::vector<gi::Color> dim;
  for (const gi::Color& e : warm) dim.push_back(0.3 * e);
  const gi::SolverResult dimmed = gi::relight(run, dim, 1e-10, s.threads);
  double worst = 0;
  for (std::size_t k = 0; k < dimmed.B.size(); ++k)
    worst = std::max(worst, gi::max_component(glm::abs(dimmed.B[k] - 0.3 * relit.B[k])) /
                                std::max(1e-300, gi::max_component(relit.B[k])));
  gi::Camera moved = s.scene.camera;
  moved.eye.x -= 150;
  const gi::Timer render_timer;
  const gi::LeafPicture view = gi::render_leaves(fresh, moved, s.display, s.seed, s.threads);
  const double render = render_timer.seconds();
  // The same view from scratch: refine, solve and render again.
  const gi::Timer scratch_timer;
  const gi::LeafPicture from_scratch = gi::render_leaves(gi::run_hierarchical(warm_scene, settings, s.threads), moved,
                                                         s.display, s.seed, s.threads);
  const double scratch = scratch_timer.seconds();
  const bool identical = from_scratch.picture.radiance.pixels == view.picture.radiance.pixels;
  gi::Table table("What can change without new links (a warm light, 0.5 0.3 0.1 of the old; no truth of it exists)",
                  {{"what"}, {"s", 3}, {"differs from the full recompute by %", 2}});
  table.add_row({"full recompute (refine and solve)", fresh.seconds, 0.0});
  table.add_row({"the old links, re-solved", resolve, 100 * gi::picture_error(a, b, s.mask).relative_rms});
  table.add_row({"first solve, old light (for scale)", first, std::string("-")});
  table.add_row({"a new camera: the picture only", render, std::string("-")});
  table.add_row({"a new camera: from scratch", scratch, std::string("-")});
  lesson.table(table, "relight");
  lesson.say("dimmer: the solve with the light x 0.3 differs from 0.3 x the solution by at most " +
             gi::format_number(worst, 1, gi::Format::Scientific) + " (relative): linear in E");
  lesson.say(std::string("the new camera's picture from the kept solution and from scratch: ") +
             (identical ? "identical, byte for byte" : "DIFFERENT"));
  lesson.diagram(gi::side_by_side({relit_shown,
                                   gi::render_leaves(fresh, s.scene.camera, shown, s.seed, s.threads).picture.shown, view.picture.shown}),
                 "relight", "the warm light re-solved on the old links; fully recomputed; seen from elsewhere", 1);
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("13_hierarchical", "Hierarchical radiosity on the Cornell box against the path-traced truth: "
                                       "thresholds, links against leaves, error against time beside uniform meshes, "
                                       "failures, relighting.");
  Setup s;
  s.scene = gi::cornell_box();
  s.settings.exact_direct = true;
  // 3e-4, not the library's 1e-4: a third of the leaves and time, the error at BF_eps
  // 1e-3 (direct per pixel) 2.05% against 1.95% (docs/13); --min-area 1e-4 for the full size.
  s.settings.refinement.min_area = 3e-4;
  s.per_pixel.light_cells = 4;  // as lesson 12: a pixel's shadow is averaged over its 2 x 2 eye rays anyway
  bool skip_studies = false;
  lesson.options()
      .add("--threshold", s.settings.refinement.threshold, "BF_eps of the rounds table, failures and relighting", 1e-6, 1.0)
      .add("--f-threshold", s.settings.refinement.form_factor_threshold, "F_eps of the first round", 1e-4, 10.0)
      .add("--min-area", s.settings.refinement.min_area, "no node below this fraction of the scene's area", 1e-7, 0.1)
      .add("--uniform-elements", s.uniform_elements, "the finest uniform mesh compared (and a quarter of it)", 100, 20000)
      .add("--exposure", s.exposure, "multiplies the radiance before display", 0.01, 100.0)
      .add_flag("--skip-studies", skip_studies, "only the thresholds (no uniform meshes, failures or relighting)");
  const int size = 256;  // the stored truth's
  std::optional<gi::Truth> truth;
  lesson.add_check([&] {  // before any work: a damaged or stale truth stops the lesson in one line
    truth = gi::stored_truth(std::string(GI_SOURCE_DIR) + "/lessons/references", "cornell", size, size);
  });
  return lesson.run(argc, argv, [&] {
    s.threads = lesson.threads();
    s.seed = s.settings.refinement.seed = lesson.seed();
    s.display.width = s.display.height = size;
    s.truth = truth->mean;
    s.mask = gi::interior_blocks(s.scene.surfaces, s.scene.camera, size, size, 8);
    const gi::PictureError noise = gi::reference_noise(truth->standard_error, truth->mean, s.mask);
    lesson.say("truth: the path-traced box, " + std::to_string(truth->spp) + " spp, its own noise " +
               percent(noise.relative_rms) + "% relative RMS over " + std::to_string(s.mask.count()) +
               " interior 8x8 blocks");
    gi::Chart chart{"Error against time: hierarchical and uniform meshes", "seconds", "error against the truth (%)",
                    true, true, {}};
    const gi::Mesh surfaces = gi::make_mesh(s.scene.surfaces, {1e300, 1});  // one element per surface
    const gi::FormFactorScene surface_shapes(gi::element_shapes(surfaces));
    const gi::DirectLighting lights(surfaces, s.per_pixel.light_cells);
    const gi::DirectRadiance direct{surface_shapes, surfaces, lights};
    s.direct = &direct;
    thresholds(s, chart, lesson);
    if (skip_studies) return;
    uniform_meshes(s, chart, lesson);
    lesson.chart(chart, "error_time");
    stability(s, lesson);
    what_can_change(s, lesson);
  });
}
