// Graded tests of exercises 13.2 (the visibility of a link), 13.3 (gathering over
// links) and 13.4 (push-pull). One point per test.
#include <gtest/gtest.h>

#include <cmath>

#include "gi/radiosity/hierarchical/hierarchy.hpp"
#include "gi/radiosity/hierarchical/push_pull.hpp"
#include "gi/radiosity/hierarchical/visibility.hpp"
#include "support/print.hpp"

using gi::Color;

namespace {

gi::Surface square(gi::vec3 c0, gi::vec3 u, gi::vec3 v) { return {"", {c0, c0 + u, c0 + u + v, c0 + v}, Color(0.5)}; }

// Two unit squares facing each other one apart (the bottom at y = 0 facing up, the
// top at y = 1 facing down) and, optionally, a blocker at y = 0.5 over x in [0, w].
gi::Hierarchy facing_squares(double blocker_width) {
  std::vector<gi::Surface> s = {square({0, 0, 0}, {0, 0, 1}, {1, 0, 0}), square({0, 1, 0}, {1, 0, 0}, {0, 0, 1})};
  if (blocker_width > 0) s.push_back(square({0, 0.5, 0}, {blocker_width, 0, 0}, {0, 0, 1}));
  return gi::make_hierarchy(s);
}

gi::FormFactorScene world(const gi::Hierarchy& h) {
  std::vector<gi::Polygon> shapes;
  for (std::size_t s = 0; s < h.surfaces.size(); ++s) shapes.push_back(h.nodes[s].shape);
  return gi::FormFactorScene(shapes);
}

// A flat trapezoid facing up: its four children have four different areas.
gi::Hierarchy trapezoid() {
  gi::Surface t{"trapezoid", {gi::vec3(0, 0, 0), gi::vec3(0, 0, 4), gi::vec3(2, 0, 3), gi::vec3(2, 0, 1)}, Color(0.5),
                Color(1.0, 2.0, 3.0)};
  return gi::make_hierarchy({t});
}

}  // namespace

TEST(Ex13_2_Visibility, AllOrNothingWhereNothingOrEverythingIsInTheWay) {
  gi::Hierarchy open = facing_squares(0);
  EXPECT_NEAR(gi::link_visibility(world(open), open, 1, 0, 4, 1).V, 1.0, 1e-12) << "nothing in between: every ray gets through";
  gi::Hierarchy closed = facing_squares(1);
  EXPECT_EQ(gi::link_visibility(world(closed), closed, 1, 0, 4, 1).V, 0.0) << "a blocker over the whole gap: none does";
}

TEST(Ex13_2_Visibility, AHalfBlockerHidesHalfTheLight) {
  // The blocker covers x < 1/2 halfway up: a ray from (x1, 1) to (x2, 0) is stopped iff
  // (x1 + x2) / 2 < 1/2. Mirroring both ends (x -> 1 - x) swaps stopped and free rays
  // and keeps their kernel, so exactly half the light gets through. 8 x 8 rays per
  // seed: a standard error below 0.07 per seed; over 40 seeds the mean's is below
  // 0.011, and we allow 0.04 (3.6 sigma: a false failure about once in 3 000 runs).
  gi::Hierarchy h = facing_squares(0.5);
  const gi::FormFactorScene blockers = world(h);
  double sum = 0;
  bool partial = true;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const double v = gi::link_visibility(blockers, h, 1, 0, 8, seed).V;
    partial = partial && v > 0 && v < 1;
    sum += v;
  }
  EXPECT_TRUE(partial) << "visibility is the share of the light that gets through, not all-or-nothing";
  EXPECT_NEAR(sum / 40, 0.5, 0.04) << "half the light between the squares is stopped by the blocker";
}

TEST(Ex13_2_Visibility, WeighsEachRayByWhatItWouldCarry) {
  // The same rays by hand: each weighs cos_p cos_q / r^2, the form factor's kernel.
  gi::Hierarchy h = facing_squares(0.5);
  const gi::FormFactorScene blockers = world(h);
  const std::vector<gi::ShadowRay> rays = gi::shadow_rays(h, 1, 0, 4, 5);
  double all = 0, through = 0;
  for (const gi::ShadowRay& ray : rays) {
    const gi::vec3 d = ray.to - ray.from;
    const double r2 = gi::dot(d, d);
    const double w = gi::dot(d, h.nodes[1].shape.normal) * -gi::dot(d, h.nodes[0].shape.normal) / (r2 * r2);
    all += w;
    if (blockers.visible(ray.from, ray.to)) through += w;
  }
  EXPECT_NEAR(gi::link_visibility(blockers, h, 1, 0, 4, 5).V, through / all, 1e-12)
      << "a near ray carries more light than a far, slanting one: weigh each by cos_p cos_q / r^2";
}

TEST(Ex13_2_Visibility, SaysWhichQuarterOfTheSourceTheLightReaches) {
  // The blocker hides more of the source's half x < 1/2 (its quarters 0 and 1: the
  // bottom square's second parameter runs along x) than of the other.
  gi::Hierarchy h = facing_squares(0.5);
  const gi::FormFactorScene blockers = world(h);
  double hidden_half = 0, open_half = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const gi::LinkVisibility v = gi::link_visibility(blockers, h, 1, 0, 8, seed);
    EXPECT_NEAR(v.by_quarter[0] + v.by_quarter[1] + v.by_quarter[2] + v.by_quarter[3], v.V, 1e-12)
        << "the quarters' shares add up to V";
    hidden_half += v.by_quarter[0] + v.by_quarter[1], open_half += v.by_quarter[2] + v.by_quarter[3];
  }
  // Expected about 1/8 and 3/8 of the light (a far end beyond the blocker's edge is
  // seen from fewer points): asserted only that the open half gets twice as much.
  EXPECT_GT(open_half, 2 * hidden_half) << "add each ray's weight to the quarter its end lies in (ShadowRay::quarter)";
}

TEST(Ex13_2_Visibility, RaysThatCannotCarryLightDoNotCount) {
  // A floor x in [0, 2] facing up and a wall at x = 1 facing -x: from the floor beyond
  // x = 1 the wall shows its back. Those rays carry no light (F leaves that part out
  // already); of the others, nothing stops any.
  gi::Hierarchy h = gi::make_hierarchy({square({0, 0, 0}, {0, 0, 1}, {2, 0, 0}),
                                        square({1, 0.1, 0}, {0, 1, 0}, {0, 0, 1})});
  EXPECT_NEAR(gi::link_visibility(world(h), h, 0, 1, 8, 3).V, 1.0, 1e-12)
      << "count only the rays that start in front of the source and end in front of the receiver";
}

TEST(Ex13_2_Visibility, SameRaysForTheSameSeed) {
  gi::Hierarchy h = facing_squares(0.5);
  const gi::FormFactorScene blockers = world(h);
  const gi::LinkVisibility a = gi::link_visibility(blockers, h, 1, 0, 4, 7), b = gi::link_visibility(blockers, h, 1, 0, 4, 7);
  EXPECT_EQ(a.V, b.V) << "cast the rays of shadow_rays(hierarchy, receiver, source, n, seed): the same every time";
  EXPECT_EQ(a.by_quarter, b.by_quarter) << "and the same shares of the quarters";
}

TEST(Ex13_3_Gather, AddsFTimesVisibilityTimesBOverTheLinks) {
  gi::Hierarchy h = facing_squares(1);  // three leaves: 0, 1 and 2
  gi::Node& p = h.nodes[0];
  p.rho = Color(0.5, 0.25, 1.0);
  p.links = {gi::Link{0, 1, 0.2, 0.1, 1.0}, gi::Link{0, 2, 0.4, 0.1, 0.5}};
  const std::vector<Color> B = {Color(100.0), Color(1.0, 2.0, 3.0), Color(10.0)};
  const Color g = gi::gather(h, p, B);
  // rho (0.2 * 1 * B_1 + 0.4 * 0.5 * B_2)
  EXPECT_NEAR(g.x, 0.5 * (0.2 * 1 + 0.2 * 10), 1e-12) << "rho_p times the sum over links of F V B_source";
  EXPECT_NEAR(g.y, 0.25 * (0.2 * 2 + 0.2 * 10), 1e-12) << "channel by channel: rho_p.y and B_q.y";
  EXPECT_NEAR(g.z, 1.0 * (0.2 * 3 + 0.2 * 10), 1e-12) << "channel by channel: rho_p.z and B_q.z";
}

TEST(Ex13_3_Gather, VisibilityScalesTheLightALinkCarries) {
  gi::Hierarchy h = facing_squares(0);
  gi::Node& p = h.nodes[0];
  p.rho = Color(1.0);
  p.links = {gi::Link{0, 1, 0.5, 0.5, 0.25}};
  EXPECT_NEAR(gi::gather(h, p, {Color(0.0), Color(8.0)}).x, 0.5 * 0.25 * 8, 1e-12)
      << "a link a quarter visible carries a quarter of F B";
  p.links.clear();
  EXPECT_EQ(gi::gather(h, p, {Color(0.0), Color(8.0)}), Color(0.0)) << "no links, nothing gathered";
}

TEST(Ex13_3_Gather, ASplitSourceSendsEachQuarterByItsOwnRadiosity) {
  gi::Hierarchy h = facing_squares(0);
  gi::split(h, 1);  // children 2, 3, 4, 5
  gi::Link link{0, 1, 0.5, 0.5, 0.6};
  link.by_quarter = {0.1f, 0.2f, 0.3f, 0.0f};
  h.nodes[0].rho = Color(1.0);
  h.nodes[0].links = {link};
  const std::vector<Color> B = {Color(0.0), Color(7.0), Color(1.0), Color(2.0), Color(3.0), Color(100.0)};
  EXPECT_NEAR(gi::gather(h, h.nodes[0], B).x, 0.5 * (0.1 * 1 + 0.2 * 2 + 0.3 * 3), 1e-6)
      << "the source has children: F times the sum over its quarters of that quarter's share of V times its B";
}

TEST(Ex13_4_PushPull, ALeafGetsItsEmissionAndWhatItAndItsAncestorsGathered) {
  gi::Hierarchy h = trapezoid();
  gi::split(h, 0);
  const int child = h.nodes[0].children[1];
  gi::split(h, child);
  h.nodes[0].gathered = Color(0.5);
  h.nodes[child].gathered = Color(0.25);
  const int grandchild = h.nodes[child].children[2];
  h.nodes[grandchild].gathered = Color(0.125);
  gi::push_pull(h, 0, Color(0.0));
  EXPECT_EQ(h.nodes[grandchild].B, Color(1.0, 2.0, 3.0) + Color(0.5 + 0.25 + 0.125))
      << "B_leaf = source (its E) + everything its ancestors gathered (pushed down) + its own";
  EXPECT_EQ(h.nodes[h.nodes[0].children[0]].B, Color(1.5, 2.5, 3.5))
      << "a leaf directly under the root gets the root's gathered light too";
  // A balanced leaf (balance.hpp) takes what reaches it times its gather_scale.
  h.nodes[h.nodes[0].children[0]].gather_scale = 1.25;
  gi::push_pull(h, 0, Color(0.0));
  EXPECT_EQ(h.nodes[h.nodes[0].children[0]].B, Color(1.0, 2.0, 3.0) + 1.25 * Color(0.5))
      << "B_leaf = source + gather_scale * (pushed + gathered): the scale multiplies what reaches the leaf, not its "
         "source";
}

TEST(Ex13_4_PushPull, AParentHoldsTheAreaWeightedMeanOfItsChildren) {
  gi::Hierarchy h = trapezoid();
  gi::split(h, 0);
  for (int k = 0; k < 4; ++k) h.nodes[h.nodes[0].children[k]].gathered = Color(1.0 + k);
  const Color root = gi::push_pull(h, 0, Color(0.0));
  Color sum(0.0);
  double area = 0;
  for (int c : h.nodes[0].children) sum += h.nodes[c].shape.area * h.nodes[c].B, area += h.nodes[c].shape.area;
  EXPECT_LT(gi::length(root - sum / area), 1e-12) << "pull up the mean weighted by the children's areas (they differ here)";
  EXPECT_EQ(h.nodes[0].B, root) << "the parent keeps the pulled B: it is what links from it carry";
}

TEST(Ex13_4_PushPull, ABuriedChildDoesNotDimItsParent) {
  // A child wholly inside a solid (the floor under a block) has no open area: no light
  // leaves it, so the mean a link from its parent carries leaves it out.
  gi::Hierarchy h = trapezoid();
  gi::split(h, 0);
  const int buried = h.nodes[0].children[2];
  h.nodes[buried].open_area = 0;
  h.nodes[0].open_area -= h.nodes[buried].shape.area;
  for (int k = 0; k < 4; ++k) h.nodes[h.nodes[0].children[k]].gathered = Color(1.0 + k);
  const Color root = gi::push_pull(h, 0, Color(0.0));
  Color sum(0.0);
  double area = 0;
  for (int c : h.nodes[0].children)
    if (c != buried) sum += h.nodes[c].shape.area * h.nodes[c].B, area += h.nodes[c].shape.area;
  EXPECT_LT(gi::length(root - sum / area), 1e-12) << "weigh the children by their open areas (Node::open_area)";
}

TEST(Ex13_4_PushPull, KeepsThePower) {
  gi::Hierarchy h = trapezoid();
  gi::split(h, 0);
  gi::split(h, h.nodes[0].children[3]);
  double expected = h.nodes[0].shape.area * 1.0;  // emitted, red channel
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    h.nodes[n].gathered = Color(0.1 * static_cast<double>(n));
    expected += h.nodes[n].shape.area * h.nodes[n].gathered.x;
  }
  gi::push_pull(h, 0, Color(0.0));
  double power = 0;
  for (int n : gi::leaves(h)) power += h.nodes[n].shape.area * h.nodes[n].B.x;
  EXPECT_NEAR(power, expected, 1e-9 * expected) << "light gathered on a node lands on all its leaves: no more, no less";
  EXPECT_NEAR(h.nodes[0].shape.area * h.nodes[0].B.x, expected, 1e-9 * expected) << "the root holds the mean over all";
}
