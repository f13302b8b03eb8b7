// Lesson 13, step 2: links against leaves as the mesh may grow finer (steps.hpp).
#include <string>

#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"
#include "gi/report/table.hpp"
#include "steps.hpp"

namespace lesson13 {

// At the lesson's BF_eps, all light by links, the smallest node allowed shrinks from
// 3e-3 to 3e-5 of the scene's area: the leaves grow by a factor of about 70. A uniform
// mesh of n elements needs n(n - 1) form factors; Hanrahan, Salzman and Aupperle's
// claim is that the hierarchy needs O(n) links, a bounded number per leaf.
void links_against_leaves(const Setup& s, gi::Lesson& lesson) {
  const double eps = s.settings.refinement.threshold;
  gi::Table table("Links against leaves at BF_eps " + gi::format_number(eps, 0, gi::Format::Scientific) +
                      ", all light by links, the smallest node allowed ever smaller",
                  {{"min area", 0, gi::Format::Scientific}, {"leaves"}, {"links"}, {"links / leaf", 1},
                   {"uniform n(n-1)"}, {"n(n-1) / links", 0}});
  gi::Series links{"hierarchical: links", {}, {}}, square{"uniform mesh: n(n-1) form factors", {}, {}};
  for (const double min_area : {3e-3, 1e-3, 3e-4, 1e-4, 3e-5}) {
    gi::HierarchicalSettings settings = with(s.settings, eps, false);
    settings.refinement.min_area = min_area;
    const gi::HierarchicalRun run = gi::run_hierarchical(s.scene, settings, s.threads);
    const double leaves = run.result.rounds.back().leaves, n_links = static_cast<double>(gi::link_count(run.hierarchy));
    const double pairs = leaves * (leaves - 1);
    table.add_row({min_area, static_cast<long long>(leaves), static_cast<long long>(n_links), n_links / leaves,
                   static_cast<long long>(pairs), pairs / n_links});
    links.x.push_back(leaves), links.y.push_back(n_links);
    square.x.push_back(leaves), square.y.push_back(pairs);
  }
  lesson.table(table, "links_against_leaves");
  lesson.chart({"Links against leaves: hierarchical beside a uniform mesh", "leaves (elements)", "links (form factors)",
                true, true, {links, square}},
               "links");
}

}  // namespace lesson13
