// The final gather over the links (link_gather.hpp): at a point it is the exact
// point-to-area light of the link's source, checked against the configuration factors
// of the heat-transfer literature; over a receiver it averages to what the solver
// gathered; far links are the solver's constants. (Against the path-traced Cornell box:
// tests/pathtrace/radiosity_agreement_test.cpp.)
#include <gtest/gtest.h>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/hierarchical/link_gather.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace {

using gi::Color;
using gi::vec3;

constexpr double rho = 0.5, E = 1.0;

// A unit floor (z = 0, rho) and, standing on its edge y = 0, a unit wall that glows
// (E, no reflection), or a unit ceiling `gap` above the floor. Neither may be cut
// (minimum area the whole scene's), so the floor has one link from the light.
gi::HierarchicalRun floor_and_light(bool wall, double gap = 1) {
  const gi::Surface floor{"floor", {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}, Color(rho)};
  const gi::Surface light =
      wall ? gi::Surface{"wall", {vec3(0, 0, 0), vec3(0, 0, 1), vec3(1, 0, 1), vec3(1, 0, 0)}, Color(0.0), Color(E)}
           : gi::Surface{"ceiling", {vec3(0, 0, gap), vec3(0, 1, gap), vec3(1, 1, gap), vec3(1, 0, gap)}, Color(0.0),
                         Color(E)};
  gi::HierarchicalSettings s;
  s.refinement.min_area = 1;
  return gi::run_hierarchical({"two squares", {floor, light}, {}}, s, 1);
}

TEST(LinkGather, AtAPointIsTheExactLightOfTheSource) {
  // The floor's one link to the wall, taken at (u, c) of the floor: rho E F(x -> wall),
  // F the differential-area-to-perpendicular-rectangle factor, the wall cut at the foot
  // of x's perpendicular into two rectangles with a corner there. The link's own light
  // is one number for the whole floor; near the wall F rises towards 1/2.
  const gi::HierarchicalRun run = floor_and_light(true);
  ASSERT_EQ(run.hierarchy.nodes[0].links.size(), 1u);
  const gi::LinkGather gather(run.hierarchy);
  for (const double u : {0.1, 0.5, 0.77})
    for (const double c : {1e-3, 0.05, 0.3, 0.9}) {
      const double F = gi::ff_point_to_perpendicular_rectangle_corner(u, 1, c) +
                       gi::ff_point_to_perpendicular_rectangle_corner(1 - u, 1, c);
      const Color g = gather.at(0, vec3(u, c, 0));
      EXPECT_NEAR(g.x, rho * E * F, 1e-12) << "at (" << u << ", " << c << ")";
    }
  // Near the wall twice the light of the middle, and more than the link hands the floor.
  EXPECT_GT(gather.at(0, vec3(0.5, 0.01, 0)).x, 2 * gather.at(0, vec3(0.5, 0.5, 0)).x);
  EXPECT_GT(gather.at(0, vec3(0.5, 0.01, 0)).x, run.hierarchy.nodes[0].gathered.x);
}

TEST(LinkGather, AveragesOverTheReceiverToWhatTheSolverGathered) {
  // The link's F is the mean of the point factor at the refinement's 3 x 3 Gauss
  // points, so the gather's mean at those points is the solver's light to round-off;
  // at 12 x 12 points it is the exact mean, rho E times the configuration factor of two
  // unit squares at right angles (0.2000), to 2e-6, ten times nearer than the 3 x 3
  // rule, which misses it by 2.4e-5 (measured: its error in the near field, docs/06).
  const gi::HierarchicalRun run = floor_and_light(true);
  const gi::LinkGather gather(run.hierarchy);
  const auto mean = [&](int order) {
    const gi::GaussRule& rule = gi::gauss_legendre(order);
    double sum = 0;
    for (int i = 0; i < order; ++i)
      for (int j = 0; j < order; ++j)
        sum += rule.weights[i] * rule.weights[j] * gather.at(0, vec3(rule.nodes[i], rule.nodes[j], 0)).x;
    return sum;
  };
  const double solver = run.hierarchy.nodes[0].gathered.x, exact = rho * E * gi::ff_perpendicular_rectangles(1, 1, 1);
  EXPECT_NEAR(mean(3), solver, 1e-14);
  EXPECT_NEAR(mean(12), exact, 2e-6 * exact);
  EXPECT_LT(std::abs(mean(12) - exact), 0.1 * std::abs(solver - exact))
      << "no nearer the closed form than the 3 x 3 rule";
}

TEST(LinkGather, AFarLinkIsTheSolversConstant) {
  // Parallel squares 10 apart: F changes by a few per cent over the floor, under
  // near_spread, so the link is read as the solver gathered it, at every point.
  const gi::HierarchicalRun run = floor_and_light(false, 10);
  const gi::Link& link = run.hierarchy.nodes[0].links.at(0);
  ASSERT_LT(link.F_max, gi::near_spread * link.F_min);
  const gi::LinkGather gather(run.hierarchy);
  for (const vec3& x : {vec3(0.01, 0.01, 0), vec3(0.5, 0.5, 0), vec3(0.9, 0.2, 0)})
    EXPECT_NEAR(gather.at(0, x).x, run.hierarchy.nodes[0].gathered.x, 1e-15);
}

TEST(LinkGather, APartlyHiddenLinkIsReadWithTheVisibilityOfThePoint) {
  // The floor under a glowing ceiling 1 up, and between them, at height 1/2, a black
  // panel over x < 0.45 (facing the floor, rho = 0: it sends nothing). The floor's one
  // link to the ceiling is partly hidden (V near a half), one number for the floor. At
  // x = 0.95 every ray of the gather reaches the ceiling: the light is the point's whole
  // view of it, rho E F(x -> ceiling), F the point-to-parallel-rectangle factor. At
  // x = 0.02 the panel hides all of them: nothing. The link's one V gave both the same
  // half (0.45 and 0.55 of it).
  const gi::Surface floor{"floor", {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}, Color(rho)};
  const gi::Surface light{"ceiling", {vec3(0, 0, 1), vec3(0, 1, 1), vec3(1, 1, 1), vec3(1, 0, 1)}, Color(0.0), Color(E)};
  const gi::Surface panel{"panel", {vec3(-0.5, -0.5, 0.5), vec3(-0.5, 1.5, 0.5), vec3(0.45, 1.5, 0.5), vec3(0.45, -0.5, 0.5)},
                          Color(0.0)};
  gi::HierarchicalSettings s;
  s.refinement.min_area = 1;
  const gi::HierarchicalRun run = gi::run_hierarchical({"shaded floor", {floor, light, panel}, {}}, s, 1);
  const gi::Node& floor_node = run.hierarchy.nodes[0];
  const gi::Link* to_light = nullptr;
  for (const gi::Link& link : floor_node.links)
    if (link.source == 1) to_light = &link;
  ASSERT_NE(to_light, nullptr);
  ASSERT_GT(to_light->visibility, 0.2);
  ASSERT_LT(to_light->visibility, 0.8);
  const gi::LinkGather gather(run.hierarchy);
  const vec3 open(0.95, 0.5, 0), shaded(0.02, 0.5, 0);
  // F(x -> ceiling): the ceiling cut at the foot of x's normal into four rectangles.
  const auto F = [](double x, double y) {
    double sum = 0;
    for (const double a : {x, 1 - x})
      for (const double b : {y, 1 - y}) sum += gi::ff_point_to_parallel_rectangle_corner(a, b, 1);
    return sum;
  };
  EXPECT_NEAR(gather.light_at(*to_light, 0, open).x, to_light->F * E, 1e-15);  // F_l V B with V = 1 there
  EXPECT_NEAR(gather.at(0, open).x, rho * E * F(0.95, 0.5), 1e-12);
  EXPECT_EQ(gather.at(0, shaded).x, 0.0);
  // What the link hands the whole floor lies between the two.
  EXPECT_GT(floor_node.gathered.x, 0.2 * gather.at(0, open).x);
}

TEST(LinkGather, VerticesHaveNoCracksAndTheSameValuesOnAnyThreads) {
  gi::HierarchicalSettings s;
  s.exact_direct = true;
  s.refinement.threshold = 1e-2;
  s.refinement.min_area = 1e-3;
  const gi::HierarchicalRun run = gi::run_hierarchical(gi::cornell_box(), s, 2);
  const gi::LeafMesh leaves = gi::leaf_mesh(run.hierarchy);
  ASSERT_FALSE(leaves.t_vertices.empty());
  const std::vector<Color> one = gi::gathered_at_vertices(run.hierarchy, leaves, 1);
  const std::vector<Color> two = gi::gathered_at_vertices(run.hierarchy, leaves, 2);
  ASSERT_EQ(one.size(), leaves.mesh.vertices.size());
  EXPECT_EQ(one, two);
  for (const gi::LeafMesh::TVertex& tv : leaves.t_vertices)
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(one[tv.vertex][c], (1 - tv.t) * one[tv.a][c] + tv.t * one[tv.b][c]);
  for (const Color& v : one) EXPECT_TRUE(gi::is_finite(v) && v.x >= 0 && v.y >= 0 && v.z >= 0);
}

}  // namespace
