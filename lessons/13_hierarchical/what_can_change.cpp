// Lesson 13, step 4: what can change without new links (steps.hpp).
#include "steps.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/render/picture_error.hpp"
#include "gi/report/table.hpp"

namespace lesson13 {

// 5. What can change: a new light on the same links (re-solve only) against a full
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

}  // namespace lesson13
