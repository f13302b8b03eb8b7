// Lesson 13 -- hierarchical radiosity: keep every surface whole and cut it only where a
// link between two pieces needs it (Hanrahan, Salzman and Aupperle 1991). The Cornell
// box at several thresholds with the leaves drawn over the shading; links against
// leaves beside the n^2 of a uniform mesh; error against time beside uniform meshes;
// where it fails; and what can change without new links: the light and the camera.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/form_factor_hemicube.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/progressive.hpp"
#include "gi/radiosity/reference_picture.hpp"
#include "gi/radiosity/solvers.hpp"
#include "gi/radiosity/vertex_colours.hpp"
#include "gi/report/lesson.hpp"

namespace {

struct Setup {
  gi::RadiosityScene scene;
  gi::ReferenceSettings reference;  // its display is every picture's
  gi::HierarchicalSettings settings;
  double exposure = 1.5;
  int threads = 2;
  int uniform_elements = 1500;  // the finest uniform mesh; also a tenth and a third of it
};

// Error of a picture against the reference picture: relative RMS over 4 x 4 blocks away
// from edges (reference_picture.hpp).
double picture_error(const gi::Image& radiance, const gi::ReferencePicture& reference) {
  return gi::relative_block_error(radiance, reference.picture.radiance, 4, reference.surface);
}

gi::HierarchicalSettings with_thresholds(gi::HierarchicalSettings s, double bf_eps, double min_area) {
  s.refinement.threshold = bf_eps;
  s.refinement.min_area = min_area;
  return s;
}

// 1. Thresholds: leaves, links, memory, time and error; each picture with its leaves.
void thresholds(const Setup& s, const gi::ReferencePicture& reference, gi::Chart& error_chart, gi::Lesson& lesson) {
  gi::Table table("Hierarchical radiosity on the Cornell box (error against the reference picture, a convergence study)",
                  {{"BF_eps", 0, gi::Format::Scientific}, {"leaves"}, {"links"}, {"links / leaf", 1},
                   {"link MB", 2}, {"s", 2}, {"error", 3}});
  gi::Series links{"hierarchical: links", {}, {}}, square{"uniform mesh: n^2 form factors", {}, {}};
  gi::Series errors{"hierarchical", {}, {}};
  std::vector<gi::Image> shown;
  for (const double eps : {1e-2, 3e-3, 1e-3, 3e-4}) {
    gi::HierarchicalRun run = gi::run_hierarchical(s.scene, with_thresholds(s.settings, eps, s.settings.refinement.min_area), s.threads);
    const gi::LeafPicture picture = gi::render_leaves(run, s.scene.camera, s.reference.display);
    gi::DisplaySettings large = s.reference.display;  // twice the size: room for the leaves' outlines
    large.width *= 2, large.height *= 2;
    const double leaves = run.result.rounds.back().leaves, n_links = static_cast<double>(gi::link_count(run.hierarchy));
    const double error = picture_error(picture.picture.radiance, reference);
    table.add_row({eps, static_cast<int>(leaves), static_cast<long long>(n_links), n_links / leaves, run.link_bytes / 1e6,
                   run.seconds, error});
    links.x.push_back(leaves), links.y.push_back(n_links);
    square.x.push_back(leaves), square.y.push_back(leaves * (leaves - 1));
    errors.x.push_back(run.seconds), errors.y.push_back(error);
    shown.push_back(gi::render_leaves(run, s.scene.camera, large).with_mesh);
    if (eps == 1e-3) {
      const gi::LeafMesh mesh = gi::leaf_mesh(run.hierarchy);
      const std::vector<gi::Color> B = gi::leaf_radiosity(run.hierarchy);
      lesson.file("leaves.ply", gi::OutputKind::Mesh, "the leaves at BF_eps 1e-3, vertex colours, T-vertices in the faces",
                  [&](const std::filesystem::path& file) {
                    gi::write_ply(mesh.mesh, gi::leaf_vertex_radiosity(mesh, B), s.exposure, file, mesh.faces);
                  });
      gi::Table rounds("Rounds at BF_eps 1e-3 (round 0: F-refinement)",
                       {{"round"}, {"nodes"}, {"leaves"}, {"links"}, {"judged"}, {"replaced"}, {"iterations"},
                        {"refine ms", 0}, {"solve ms", 0}, {"change in B", 1, gi::Format::Scientific}});
      for (const gi::RefinementRound& r : run.result.rounds)
        rounds.add_row({r.round, r.nodes, r.leaves, static_cast<long long>(r.links), static_cast<long long>(r.evaluated),
                        static_cast<long long>(r.replaced), r.iterations, 1e3 * r.refine_seconds, 1e3 * r.solve_seconds,
                        r.change});
      lesson.table(rounds, "rounds");
    }
  }
  lesson.table(table, "thresholds");
  lesson.diagram(gi::side_by_side(shown), "leaves", "the leaves at BF_eps 1e-2, 3e-3, 1e-3 and 3e-4", 1);
  lesson.chart({"Links against leaves: hierarchical beside a uniform mesh", "leaves (elements)", "links (form factors)",
                true, true, {links, square}},
               "links");
  error_chart.series.push_back(errors);
}

// 2. Uniform meshes, hemicube form factors, solved by Gauss-Seidel and by progressive
// refinement: error against whole time (form factors included).
void uniform_meshes(const Setup& s, const gi::ReferencePicture& reference, gi::Chart& chart, gi::Lesson& lesson) {
  gi::Table table("Uniform meshes (hemicube 100), to residual 1e-3; error against the same reference picture",
                  {{"elements"}, {"method"}, {"s", 2}, {"error", 3}});
  gi::Series gauss{"uniform, Gauss-Seidel", {}, {}}, shooting{"uniform, progressive", {}, {}};
  for (const int elements : {s.uniform_elements / 10, s.uniform_elements / 3, s.uniform_elements}) {
    const gi::Timer timer;
    const gi::Mesh mesh = gi::make_mesh(s.scene.surfaces, {gi::patch_size_for(s.scene.surfaces, elements, 1), 1});
    const gi::FormFactorScene receivers(gi::element_shapes(mesh));
    gi::SolverOptions options;
    options.tolerance = 1e-3;
    options.max_steps = 100'000;
    const double setup = timer.seconds();
    const gi::Timer gs_timer;
    const gi::RadiositySystem system =
        gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), 100, s.threads));
    const gi::SolverResult gs = gi::solve_gauss_seidel(system, options);
    const double gs_seconds = setup + gs_timer.seconds();
    gi::FormFactorSettings hemicube;
    const gi::Timer pr_timer;
    const gi::SolverResult pr =
        gi::solve_progressive(gi::make_system(mesh, {}), mesh, gi::patch_shooter(receivers, mesh, hemicube), options);
    const double pr_seconds = setup + pr_timer.seconds();
    const auto row = [&](const gi::SolverResult& result, double seconds, gi::Series& series) {
      const gi::Image picture = gi::render_radiosity(receivers, mesh, result.B, s.scene.camera, s.reference.display);
      const double error = picture_error(picture, reference);
      table.add_row({static_cast<int>(mesh.elements.size()), result.method, seconds, error});
      series.x.push_back(seconds), series.y.push_back(error);
    };
    row(gs, gs_seconds, gauss);
    row(pr, pr_seconds, shooting);
  }
  lesson.table(table, "uniform");
  chart.series.push_back(gauss), chart.series.push_back(shooting);
}

// 3. Where it fails, one row each, each scene against its own reference picture.
void stability(const Setup& s, gi::Lesson& lesson) {
  // The light moved to hang 1 mm in front of the back wall, facing the camera (the
  // ceiling keeps its hole): F between the light and the wall just behind its edge is
  // nearly 1/2 at the edge and falls off within millimetres.
  gi::RadiosityScene hair = s.scene;
  double back = 0;  // the back wall's depth: the largest z of any corner
  for (const gi::Surface& surface : hair.surfaces)
    for (const gi::vec3& c : surface.corners) back = std::max(back, c.z);
  for (gi::Surface& surface : hair.surfaces)
    if (gi::max_component(surface.emission) > 0) {
      for (gi::vec3& c : surface.corners) c = gi::vec3(c.x, c.z, back - 1);  // its depth becomes its height
      const gi::vec3 n = cross(surface.corners[1] - surface.corners[0], surface.corners[3] - surface.corners[0]);
      if (n.z > 0) std::swap(surface.corners[1], surface.corners[3]);  // face the room
    }
  struct Case {
    std::string what;
    const gi::RadiosityScene* scene;
    gi::HierarchicalSettings settings;
  };
  gi::HierarchicalSettings loose = s.settings;
  loose.refinement.form_factor_threshold = 2, loose.refinement.threshold = 1;
  gi::RadiosityScene occluded = gi::occluded_squares();
  occluded.camera = gi::Camera{{0, 0.4, 2.5}, {0, 1.7, 0}, {0, 1, 0}, 40};  // from below: the shadow on the top square
  const std::vector<Case> cases = {
      {"shadow edge across a large patch", &occluded, s.settings},
      {"light 1 mm in front of a wall", &hair, s.settings},
      {"thresholds so loose nothing is split", &s.scene, loose},
      {"minimum area 1e-2: the shadows unresolved", &s.scene, with_thresholds(s.settings, s.settings.refinement.threshold, 1e-2)}};
  gi::Table table("Where hierarchical radiosity goes wrong (each against its own reference picture)",
                  {{"case"}, {"leaves"}, {"links"}, {"s", 2}, {"error", 3}});
  std::vector<gi::Image> shown;
  for (const Case& c : cases) {
    const gi::ReferencePicture reference = gi::render_reference_picture(*c.scene, s.reference);
    const gi::HierarchicalRun run = gi::run_hierarchical(*c.scene, c.settings, s.threads);
    const gi::LeafPicture picture = gi::render_leaves(run, c.scene->camera, s.reference.display);
    table.add_row({c.what, run.result.rounds.back().leaves, static_cast<long long>(gi::link_count(run.hierarchy)),
                   run.seconds, picture_error(picture.picture.radiance, reference)});
    shown.push_back(picture.with_mesh);
  }
  lesson.table(table, "stability");
  lesson.diagram(gi::side_by_side(shown), "stability", "the four cases of the stability table, leaves drawn", 1);
}

// 4. What can change: a new light on the same links (re-solve only) against a full
// recompute; a dimmer is a product (the system is linear in E); a new camera is a new
// picture only.
void what_can_change(const Setup& s, gi::Lesson& lesson) {
  gi::HierarchicalRun run = gi::run_hierarchical(s.scene, s.settings, s.threads);
  const double first = run.seconds;
  std::vector<gi::Color> warm;
  for (const gi::Surface& surface : s.scene.surfaces) warm.push_back(gi::Color(0.5, 0.3, 0.1) * surface.emission);
  const gi::Timer resolve_timer;
  gi::relight(run, warm, s.settings.tolerance, s.threads);
  const double resolve = resolve_timer.seconds();
  gi::RadiosityScene warm_scene = s.scene;
  for (std::size_t k = 0; k < warm.size(); ++k) warm_scene.surfaces[k].emission = warm[k];
  const gi::HierarchicalRun fresh = gi::run_hierarchical(warm_scene, s.settings, s.threads);
  const gi::ReferencePicture reference = gi::render_reference_picture(warm_scene, s.reference);
  const gi::LeafPicture a = gi::render_leaves(run, s.scene.camera, s.reference.display);
  const gi::LeafPicture b = gi::render_leaves(fresh, s.scene.camera, s.reference.display);
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
  const gi::LeafPicture view = gi::render_leaves(fresh, moved, s.reference.display);
  const double render = render_timer.seconds();
  // The same view from scratch: refine, solve and render again.
  const gi::Timer scratch_timer;
  const gi::LeafPicture from_scratch = gi::render_leaves(gi::run_hierarchical(warm_scene, s.settings, s.threads), moved,
                                                         s.reference.display);
  const double scratch = scratch_timer.seconds();
  const bool identical = from_scratch.picture.radiance.pixels == view.picture.radiance.pixels;
  gi::Table table("What can change without new links (a warm light, 0.5 0.3 0.1 of the old)",
                  {{"what"}, {"s", 3}, {"error against the reference", 3}});
  table.add_row({"full recompute (refine and solve)", fresh.seconds, picture_error(b.picture.radiance, reference)});
  table.add_row({"the old links, re-solved", resolve, picture_error(a.picture.radiance, reference)});
  table.add_row({"first solve, old light (for scale)", first, std::string("-")});
  table.add_row({"a new camera: the picture only", render, std::string("-")});
  table.add_row({"a new camera: from scratch", scratch, std::string("-")});
  lesson.table(table, "relight");
  lesson.say("dimmer: the solve with the light x 0.3 differs from 0.3 x the solution by at most " +
             gi::format_number(worst, 1, gi::Format::Scientific) + " (relative): linear in E");
  lesson.say(std::string("the new camera's picture from the kept solution and from scratch: ") +
             (identical ? "identical, byte for byte" : "DIFFERENT"));
  lesson.diagram(gi::side_by_side({a.picture.shown, b.picture.shown, view.picture.shown}), "relight",
                 "the warm light re-solved on the old links; fully recomputed; seen from elsewhere", 1);
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("13_hierarchical", "Hierarchical radiosity on the Cornell box: thresholds, links against leaves, "
                                       "error against time beside uniform meshes, failures, relighting.");
  Setup s;
  s.scene = gi::cornell_box();
  s.reference.display.width = s.reference.display.height = 160;
  s.settings.refinement.threshold = 1e-3;
  s.settings.refinement.min_area = 1e-4;
  bool skip_studies = false;
  lesson.add_image_size(s.reference.display.width, s.reference.display.height);
  lesson.options()
      .add("--threshold", s.settings.refinement.threshold, "BF_eps for the stability and relighting runs", 1e-6, 1.0)
      .add("--f-threshold", s.settings.refinement.form_factor_threshold, "F_eps of the first round", 1e-4, 10.0)
      .add("--min-area", s.settings.refinement.min_area, "no node below this fraction of the scene's area", 1e-7, 0.1)
      .add("--reference-elements", s.reference.elements, "uniform mesh of the reference's indirect light", 50, 20000)
      .add("--uniform-elements", s.uniform_elements, "the finest uniform mesh of the error-against-time chart", 100, 20000)
      .add("--exposure", s.exposure, "multiplies the radiance before display", 0.01, 100.0)
      .add_flag("--skip-studies", skip_studies, "only the thresholds (no uniform meshes, failures or relighting)");
  return lesson.run(argc, argv, [&] {
    s.threads = lesson.threads();
    s.reference.display.threads = lesson.threads();
    s.reference.display.seed = lesson.seed();
    s.reference.display.white = 1 / s.exposure;
    s.settings.refinement.seed = lesson.seed();
    const gi::Timer timer;
    const gi::ReferencePicture reference = gi::render_reference_picture(s.scene, s.reference);
    lesson.say("reference picture: exact direct light at every pixel sample, indirect light on " +
               std::to_string(reference.elements) + " uniform elements (" +
               gi::format_number(100 * reference.indirect_share, 0, gi::Format::Fixed) + "% of the picture), " +
               gi::format_number(timer.seconds(), 1, gi::Format::Fixed) + " s");
    lesson.picture(reference.picture.radiance, "reference", "the reference picture",
                   {s.scene.camera, s.reference.display.width, s.reference.display.height,
                    gi::describe_pixel_samples(s.reference.display)},
                   s.exposure, &reference.picture.shown);
    gi::Chart chart{"Error against time: uniform meshes and hierarchical", "seconds", "error", true, true, {}};
    thresholds(s, reference, chart, lesson);
    if (skip_studies) return;
    uniform_meshes(s, reference, chart, lesson);
    lesson.chart(chart, "error_time");
    stability(s, lesson);
    what_can_change(s, lesson);
  });
}
