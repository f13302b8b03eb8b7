// Hidden graded tests of lab 13 (the autograder's; kits leave hidden/ out): random
// links and random quadtrees, checked against properties any right answer has, not
// against a second solution. One point per test.
#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/radiosity/hierarchical/oracle.hpp"
#include "gi/radiosity/hierarchical/push_pull.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "support/print.hpp"

TEST(Ex13_1_RandomLinks, ConstantTransferIsAcceptedAndALooserThresholdNeverRefinesMore) {
  gi::Rng rng(1301);
  for (int k = 0; k < 2000; ++k) {
    gi::Link link{0, 1, rng.uniform(), rng.uniform(), rng.uniform() < 0.3 ? 1.0 : rng.uniform()};
    const double a = rng.uniform(), b = rng.uniform();
    link.F_min = static_cast<float>(std::min(a, b) * link.F), link.F_max = static_cast<float>(std::max(a, b) * 2 * link.F);
    const gi::Brightness brightness{0.5 * rng.uniform(), 0.5 + 0.5 * rng.uniform()};
    const double threshold = 0.1 * rng.uniform();
    const gi::Refinement tight = gi::oracle(link, brightness, threshold, true, true);
    const gi::Refinement loose = gi::oracle(link, brightness, 10 * threshold + 1e-3, true, true);
    if (tight == gi::Refinement::Accept) {
      ASSERT_EQ(loose, gi::Refinement::Accept) << "accepted at threshold " << threshold << " but refined at a looser one";
    }
    gi::Link flat{0, 1, link.F, link.F_back, 1.0};
    flat.F_min = flat.F_max = static_cast<float>(link.F);
    ASSERT_EQ(gi::oracle(flat, {0.7, 0.7}, 1e-6, true, true), gi::Refinement::Accept)
        << "F the same at every point of the receiver, a uniform source, nothing in between: the link is exact";
  }
}

TEST(Ex13_4_RandomTrees, PushPullKeepsThePowerOfAnyTree) {
  gi::Rng rng(1304);
  gi::Hierarchy h = gi::make_hierarchy(gi::closed_box().surfaces);
  for (int k = 0; k < 60; ++k) {
    const int n = static_cast<int>(rng.uniform() * static_cast<double>(h.nodes.size()));
    if (h.nodes[n].leaf()) gi::split(h, n);
  }
  double expected = 0;
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    gi::Node& node = h.nodes[n];
    node.gathered = gi::Color(rng.uniform(), rng.uniform(), rng.uniform());
    expected += node.shape.area * (node.gathered.x + node.gathered.y + node.gathered.z);
    if (static_cast<int>(n) < static_cast<int>(h.surfaces.size()))
      expected += node.shape.area * (node.source.x + node.source.y + node.source.z);
  }
  double power = 0;
  for (int root = 0; root < static_cast<int>(h.surfaces.size()); ++root) {
    const gi::Color b = gi::push_pull(h, root, gi::Color(0.0));
    power += h.nodes[root].shape.area * (b.x + b.y + b.z);
  }
  EXPECT_NEAR(power, expected, 1e-9 * expected)
      << "the roots' power must be what was emitted plus what every node gathered: push every node's gathered "
         "light down to all leaves below it, and pull back up with area weights";
}
