// Lesson 13, step 3: where it fails (steps.hpp).
#include "steps.hpp"

#include <string>
#include <utility>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"
#include "gi/report/table.hpp"

namespace lesson13 {

// 4. Where it fails, one row each, against the same truth: thresholds so loose that
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

}  // namespace lesson13
