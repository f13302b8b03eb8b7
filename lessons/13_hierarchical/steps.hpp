#pragma once
// Lesson 13, steps 2 to 5, each in its own file beside main.cpp: links against leaves
// (links_against_leaves.cpp), where the hierarchy cuts (where_it_cuts.cpp), one leaf's links
// (one_leafs_links.cpp), the
// uniform meshes beside the hierarchy
// (uniform_meshes.cpp), where it fails (stability.cpp), and what can change without
// new links (what_can_change.cpp).
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "scoring.hpp"

namespace lesson13 {

// The links table and chart: leaves and links as the smallest node allowed shrinks.
void links_against_leaves(const Setup& s, gi::Lesson& lesson);

// The picture of where a loose threshold's leaves crowd, beside a uniform mesh of as
// many elements.
void where_it_cuts(const Setup& s, gi::Lesson& lesson);

// The links that light one floor leaf of `run`, drawn over `picture` (radiance, shown
// at the lesson's exposure).
void one_leafs_links(const Setup& s, const gi::HierarchicalRun& run, const gi::Image& picture, gi::Lesson& lesson);

// The uniform table; adds the uniform meshes' curves to `chart`.
void uniform_meshes(const Setup& s, gi::Chart& chart, gi::Lesson& lesson);

// The stability table and its pictures.
void stability(const Setup& s, gi::Lesson& lesson);

// The relight table, the dimmer's and the new camera's lines, and their pictures.
void what_can_change(const Setup& s, gi::Lesson& lesson);

}  // namespace lesson13
