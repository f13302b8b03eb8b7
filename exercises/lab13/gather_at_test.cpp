// Graded tests of exercise 13.5 (gathering at a point: the final gather). One point per test.
#include <gtest/gtest.h>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/hierarchical/link_gather.hpp"
#include "support/print.hpp"

namespace {

using gi::Color;
using gi::vec3;

const Color rho(0.5, 0.25, 0.125);  // a different reflectance per channel
constexpr double E = 2;

// A unit floor (z = 0) and a unit wall standing on its edge y = 0 that glows (B = E),
// the floor's root given one link from the wall by hand: F = 0.2 (two unit squares at
// right angles), wholly visible, its F over the floor from 0.01 to 0.5 (a near link).
// Nothing here runs exercises 13.1-13.4: a bug there costs no points here.
gi::Hierarchy floor_and_wall() {
  const gi::Surface floor{"floor", {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}, rho};
  const gi::Surface wall{"wall", {vec3(0, 0, 0), vec3(0, 0, 1), vec3(1, 0, 1), vec3(1, 0, 0)}, Color(0.0), Color(E)};
  gi::Hierarchy h = gi::make_hierarchy({floor, wall});
  h.nodes[1].B = Color(E);
  gi::Link link{0, 1, gi::ff_perpendicular_rectangles(1, 1, 1), gi::ff_perpendicular_rectangles(1, 1, 1), 1.0};
  link.F_min = 0.01f, link.F_max = 0.5f;
  h.nodes[0].links.push_back(link);
  return h;
}

// F from a point of the floor at (u, c) to the whole wall: the wall cut at the foot of
// the point's perpendicular into two rectangles with a corner there (Howell's catalogue).
double F_to_wall(double u, double c) {
  return gi::ff_point_to_perpendicular_rectangle_corner(u, 1, c) +
         gi::ff_point_to_perpendicular_rectangle_corner(1 - u, 1, c);
}

}  // namespace

TEST(Ex13_5_GatherAtAPoint, IsTheExactLightOfTheSourceAtThePoint) {
  const gi::Hierarchy h = floor_and_wall();
  const gi::LinkGather gather(h);
  for (const double c : {0.02, 0.5}) {
    const Color g = gather.at(0, vec3(0.5, c, 0));
    EXPECT_NEAR(g.x, rho.x * E * F_to_wall(0.5, c), 1e-9)
        << "at distance " << c << " from the wall the light is rho E F(x -> wall), F the point-to-polygon factor "
           "from x itself: scale the link's light by F(x -> q) / F_l (the link's F is the mean over the floor)";
  }
}

TEST(Ex13_5_GatherAtAPoint, RisesTowardsTheCrease) {
  const gi::Hierarchy h = floor_and_wall();
  const gi::LinkGather gather(h);
  const double near = gather.at(0, vec3(0.5, 0.01, 0)).x, far = gather.at(0, vec3(0.5, 0.9, 0)).x;
  EXPECT_GT(near, 3 * far) << "beside the wall the floor sees half its sky glow, far from it a sliver: a link's one "
                              "number for the whole floor (the solver's) cannot show that; F taken at x does";
}

TEST(Ex13_5_GatherAtAPoint, ReflectsEachChannelByItsOwnRho) {
  const gi::Hierarchy h = floor_and_wall();
  const gi::LinkGather gather(h);
  const Color g = gather.at(0, vec3(0.3, 0.2, 0));
  const double F = F_to_wall(0.3, 0.2);
  EXPECT_NEAR(g.x, 0.5 * E * F, 1e-9) << "red: rho 0.5 times what arrives";
  EXPECT_NEAR(g.y, 0.25 * E * F, 1e-9) << "green: rho 0.25; multiply by the leaf's rho, channel by channel";
  EXPECT_NEAR(g.z, 0.125 * E * F, 1e-9) << "blue: rho 0.125";
}

TEST(Ex13_5_GatherAtAPoint, CountsTheAncestorsLinks) {
  gi::Hierarchy h = floor_and_wall();
  gi::split(h, 0);  // the floor's four quarters: leaves without links of their own
  const int quarter = h.nodes[0].children[0];  // [0, 1/2] x [0, 1/2]
  const gi::LinkGather gather(h);
  EXPECT_NEAR(gather.at(quarter, vec3(0.25, 0.1, 0)).x, rho.x * E * F_to_wall(0.25, 0.1), 1e-9)
      << "this leaf has no links; its light came through its parent's link, which push-pull handed down: walk "
         "from the leaf up to the root (Node::parent) and gather every node's links";
}

TEST(Ex13_5_GatherAtAPoint, KeepsTheFarLinksAsTheyAre) {
  // The same link marked far (its F within near_spread over the floor): its light is
  // in far_, and the gather is rho F V B at every point, as the solver gathers it.
  gi::Hierarchy h = floor_and_wall();
  gi::Link& link = h.nodes[0].links[0];
  link.F_min = 0.19f, link.F_max = 0.21f;
  const gi::LinkGather gather(h);
  const Color g = gather.at(0, vec3(0.5, 0.05, 0));
  EXPECT_GT(g.x, 0) << "a far link's light counts too: add far_[node] for the leaf and each ancestor";
  EXPECT_NEAR(g.x, rho.x * link.F * E, 1e-12) << "far links count as they are (far_), as the solver gathered them";
}

TEST(Ex13_5_GatherAtAPoint, APartlyHiddenLinkIsReadAsThePointSeesIt) {
  // The floor under a glowing ceiling 1 up, a black panel at height 1/2 over x < 0.45;
  // the floor's link from the ceiling made by hand with V = 1/2 (a shadow's edge inside).
  // From x = 0.95 the whole ceiling is in view, from x = 0.02 none of it.
  const gi::Surface floor{"floor", {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}, rho};
  const gi::Surface light{"ceiling", {vec3(0, 0, 1), vec3(0, 1, 1), vec3(1, 1, 1), vec3(1, 0, 1)}, Color(0.0), Color(E)};
  const gi::Surface panel{"panel", {vec3(-0.5, -0.5, 0.5), vec3(-0.5, 1.5, 0.5), vec3(0.45, 1.5, 0.5), vec3(0.45, -0.5, 0.5)},
                          Color(0.0)};
  gi::Hierarchy h = gi::make_hierarchy({floor, light, panel});
  h.nodes[1].B = Color(E);
  const double F = gi::ff_parallel_rectangles(1, 1, 1);
  gi::Link link{0, 1, F, F, 0.5};
  link.F_min = 0.1f, link.F_max = 0.25f;
  h.nodes[0].links.push_back(link);
  const gi::LinkGather gather(h);
  double F_open = 0;  // F from (0.95, 0.5) to the ceiling: four rectangles with a corner above it
  for (const double a : {0.95, 0.05})
    for (const double b : {0.5, 0.5}) F_open += gi::ff_point_to_parallel_rectangle_corner(a, b, 1);
  EXPECT_NEAR(gather.at(0, vec3(0.95, 0.5, 0)).x, rho.x * E * F_open, 1e-9)
      << "a link with a shadow's edge inside (0 < V < 1) is read as x sees the source: take its light from "
         "light_at(link, leaf, x), not link_light (the link's one V for the whole floor)";
  EXPECT_EQ(gather.at(0, vec3(0.02, 0.5, 0)).x, 0.0) << "from under the panel the ceiling is hidden: light_at says so";
}

