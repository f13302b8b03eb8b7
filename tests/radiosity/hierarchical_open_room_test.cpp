// The balance in an open room (balance.hpp, docs/13 "In an open room"): a leaf's row
// sums to 1 only if its own view is closed, so only the leaves that see nothing but
// surfaces are balanced. The room: the unit box with a skylight, its ceiling a frame
// round a square hole [0.25, 0.75]^2. The box is convex, so nothing hides anything and
// the share of a leaf's view that leaves through the hole is exact from Lambert's
// formula; and a uniform mesh with analytic form factors, solved directly, is an exact
// system to hold the hierarchy against.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/balance.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/radiosity_system.hpp"
#include "gi/radiosity/system/solvers.hpp"

using gi::Color;
using gi::vec3;

namespace {

// The rectangle centred at `centre` spanned by u and v, facing u x v; rho = 0.5.
gi::Surface rectangle(const std::string& name, vec3 centre, vec3 u, vec3 v, Color emission) {
  const vec3 c0 = centre - 0.5 * u - 0.5 * v;
  return {name, {c0, c0 + u, c0 + u + v, c0 + v}, Color(0.5), emission};
}

// closed_box() with its ceiling cut into four pieces round the skylight; the ceiling
// frame is the light (E = 1).
gi::RadiosityScene skylight_box() {
  gi::RadiosityScene scene = gi::closed_box();
  const Color light(1.0), dark(0.0);
  std::vector<gi::Surface> faces{scene.surfaces[0]};
  faces.push_back(rectangle("ceiling z<", {0.5, 1, 0.125}, {1, 0, 0}, {0, 0, 0.25}, light));
  faces.push_back(rectangle("ceiling z>", {0.5, 1, 0.875}, {1, 0, 0}, {0, 0, 0.25}, light));
  faces.push_back(rectangle("ceiling x<", {0.125, 1, 0.5}, {0.25, 0, 0}, {0, 0, 0.5}, light));
  faces.push_back(rectangle("ceiling x>", {0.875, 1, 0.5}, {0.25, 0, 0}, {0, 0, 0.5}, light));
  for (int k = 2; k < 6; ++k) faces.push_back(scene.surfaces[k]);
  for (gi::Surface& f : faces) f.reflectance = Color(0.5);
  faces[0].emission = dark;
  scene.surfaces = faces;
  return scene;
}

const gi::Polygon skylight = gi::make_polygon({vec3(0.25, 1, 0.25), vec3(0.75, 1, 0.25), vec3(0.75, 1, 0.75),
                                               vec3(0.25, 1, 0.75)});

gi::HierarchicalRun run(double bf_eps, double min_area) {
  gi::HierarchicalSettings s;
  s.refinement.threshold = bf_eps;
  s.refinement.min_area = min_area;
  s.tolerance = 1e-12;
  return gi::run_hierarchical(skylight_box(), s, 2);
}

// What the hierarchy is held against: B on a mesh of every surface cut 8 x 8, as the
// quadtree cuts it at level 3 (576 elements), F_ij by Lambert's contour integral over j
// integrated over i (exact in a convex room), solved directly.
struct Reference {
  gi::Mesh mesh;
  std::vector<Color> B;
};
Reference reference() {
  Reference r{gi::make_mesh(skylight_box().surfaces, {1e30, 8}), {}};
  gi::FormFactorSettings analytic;
  analytic.method = gi::FormFactorMethod::Analytic;
  analytic.tolerance = 1e-6;
  const gi::RadiositySystem system =
      gi::make_system(r.mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(r.mesh)), analytic, 2));
  r.B = gi::solve_direct(system).B;
  return r;
}

struct Distance {
  double power;   // sum a B over the leaves, relative to the reference's
  double cells;  // RMS of the difference to the reference, relative, over the cells below
};
// Compared cell by cell, a cell the coarser of a leaf and an element (both halve the
// surface's parameter square, so one holds the other): a leaf against the mean of
// the elements in it, or the mean of the leaves in an element against that element.
Distance distance(const gi::Hierarchy& h, const std::vector<Color>& B, const Reference& ref) {
  const std::vector<int> leaf = gi::leaves(h);
  std::vector<int> slot(h.nodes.size(), -1);
  for (std::size_t k = 0; k < leaf.size(); ++k) slot[leaf[k]] = static_cast<int>(k);
  const auto parameters = [&](int surface, const gi::Polygon& shape) {
    return gi::unbilinear(h.surfaces[surface].corners, shape.normal, shape.centre);
  };
  // The leaf each element's centre lies in, and the element each leaf's centre lies in
  // (the nearest centre in the surface's parameter square).
  std::vector<int> leaf_of(ref.mesh.elements.size()), element_of(leaf.size(), -1);
  std::vector<double> elements_area(leaf.size(), 0.0);
  for (std::size_t e = 0; e < ref.mesh.elements.size(); ++e) {
    const gi::Element& el = ref.mesh.elements[e];
    const gi::vec2 st = parameters(el.surface, el.shape);
    leaf_of[e] = slot[gi::leaf_containing(h, el.surface, st.x, st.y)];
    elements_area[leaf_of[e]] += el.shape.area;
  }
  for (std::size_t k = 0; k < leaf.size(); ++k) {
    const gi::Node& node = h.nodes[leaf[k]];
    const gi::vec2 st = parameters(node.surface, node.shape);
    double nearest = 1e300;
    for (std::size_t e = 0; e < ref.mesh.elements.size(); ++e) {
      if (ref.mesh.elements[e].surface != node.surface) continue;
      const gi::vec2 d2 = parameters(node.surface, ref.mesh.elements[e].shape) - st;
      const double d = d2.x * d2.x + d2.y * d2.y;
      if (d < nearest) nearest = d, element_of[k] = static_cast<int>(e);
    }
  }
  // A leaf holds whole elements when theirs add up to its area; else it lies in one.
  const auto holds_elements = [&](std::size_t k) {
    return std::abs(elements_area[k] - h.nodes[leaf[k]].shape.area) < 1e-9 * h.nodes[leaf[k]].shape.area;
  };
  // Per cell: its area, the hierarchy's power and the reference's in it.
  struct Cell {
    double area = 0, ours = 0, theirs = 0;
  };
  std::vector<Cell> by_leaf(leaf.size()), by_element(ref.mesh.elements.size());
  double leaf_power = 0, reference_power = 0;
  for (std::size_t e = 0; e < ref.mesh.elements.size(); ++e) {
    const double a = ref.mesh.elements[e].shape.area, b = a * ref.B[e].x;
    reference_power += b;
    if (holds_elements(leaf_of[e])) {
      by_leaf[leaf_of[e]].theirs += b;
    } else {
      by_element[e].area = a, by_element[e].theirs = b;
    }
  }
  for (std::size_t k = 0; k < leaf.size(); ++k) {
    const gi::Node& node = h.nodes[leaf[k]];
    leaf_power += node.open_area * B[k].x;
    if (holds_elements(k)) {
      by_leaf[k].area = node.shape.area, by_leaf[k].ours = node.shape.area * B[k].x;
    } else {
      by_element[element_of[k]].ours += node.shape.area * B[k].x;
    }
  }
  double d2 = 0, b2 = 0;
  for (const std::vector<Cell>* cells : {&by_leaf, &by_element})
    for (const Cell& c : *cells)
      if (c.area > 0) d2 += (c.ours - c.theirs) * (c.ours - c.theirs) / c.area, b2 += c.theirs * c.theirs / c.area;
  return {leaf_power / reference_power - 1, std::sqrt(d2 / b2)};
}

}  // namespace

// Which leaves are balanced, against the exact share of each leaf's view that leaves
// through the skylight (Lambert's formula from its centre, exact: nothing in a convex
// box hides the hole). The ceiling frame looks down into the box and sees none of it
// (the hole lies in its own plane): all 256 of its leaves are balanced, rightly. The
// floor and the walls see out, all but four wall leaves by the ceiling, whose 0.94% of
// the view through the hole slips between the probes (measured; with the 31 probes of
// rings at 25, 50 and 75 degrees, wall leaves that saw 3.2% out were balanced).
// Asserted: every leaf that sees more than 1.5% of its view out is left as the links
// have it (scales 1), every frame leaf is balanced, and the balanced leaves' rows and
// columns are 1.
TEST(OpenRoom, OnlyTheLeavesThatSeeNothingButSurfacesAreBalanced) {
  const gi::HierarchicalRun r = run(1e-3, 3e-4);
  ASSERT_TRUE(r.result.balanced.balance.converged);
  int frame = 0, balanced = 0;
  double worst_balanced_escape = 0;
  for (int n : gi::leaves(r.hierarchy)) {
    const gi::Node& node = r.hierarchy.nodes[n];
    const double escapes = gi::form_factor_point_to_polygon(node.shape.centre, node.shape.normal, skylight);
    const bool is_balanced = node.gather_scale != 1.0 || node.send_scale != 1.0;
    balanced += is_balanced;
    if (r.hierarchy.surfaces[node.surface].name.rfind("ceiling", 0) == 0) {
      ++frame;
      EXPECT_TRUE(is_balanced) << "a leaf of the ceiling frame, which sees only the box below it";
    }
    if (is_balanced) worst_balanced_escape = std::max(worst_balanced_escape, escapes);
    if (escapes > 0.015) {
      EXPECT_FALSE(is_balanced) << "a leaf of " << r.hierarchy.surfaces[node.surface].name << " sees " << escapes
                                << " of its view out";
    }
  }
  EXPECT_EQ(frame, 256);
  EXPECT_EQ(balanced, r.result.balanced.balance.enclosed);
  EXPECT_LE(r.result.balanced.balance.after, 1e-12) << "rows and columns of the balanced leaves";
  std::cout << balanced << " of " << gi::leaves(r.hierarchy).size() << " leaves balanced (" << frame
            << " of the frame); the most a balanced leaf sees out: " << worst_balanced_escape << "\n";
}

// The balanced answer against the exact system's, beside the links alone. In an open
// room no sum gives the power (light leaves), and the balance mends only the sums it
// knows, spreading each leaf's mending over all its links in proportion; so it need not
// come nearer the truth leaf by leaf (docs/13 has finer settings, where it is 20-25%
// farther). At BF_eps 1e-2 and minimum area 1e-3, measured: the power 1.58e-3 high
// balanced and 2.11e-3 with the links alone; the RMS over the cells 0.929% and 0.940%
// (against a reference of 1/16 elements, 0.955% and 0.939%: the difference lies within
// the reference's own). Asserted: the power no farther, the RMS within 5% of the links
// alone's. Balancing the leaves that see out too (each held to 1, made by hand in
// balance.cpp) keeps light that leaves through the hole: the power 2.3e-2 high, the
// RMS 1.82%, and both assertions fail.
TEST(OpenRoom, BalancedOnlyWhereTheViewIsClosedTheAnswerIsNoFartherFromTheExactSystem) {
  const Reference ref = reference();
  gi::HierarchicalRun r = run(1e-2, 1e-3);
  const Distance balanced = distance(r.hierarchy, r.result.solution.B, ref);
  gi::unbalance(r.hierarchy);
  gi::SolverOptions options;
  options.tolerance = 1e-12;
  options.max_steps = 100000;
  const Distance alone = distance(r.hierarchy, gi::solve_links(r.hierarchy, options, 2).B, ref);
  EXPECT_LE(std::abs(balanced.power), std::abs(alone.power));
  EXPECT_LE(balanced.cells, 1.05 * alone.cells);
  std::cout << "power " << balanced.power << " balanced, " << alone.power << " the links alone; RMS over the cells "
            << balanced.cells << " and " << alone.cells << "\n";
}
