#include "gi/geometry/triangle.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using gi::vec3;

namespace {
const gi::Triangle tri{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 0};  // in z = 0, facing +z
}

TEST(Triangle, HitsInsideWithTheFrontNormal) {
  const auto hit = gi::intersect(gi::Ray{{0.5, 0.5, 3}, {0, 0, -1}}, tri);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 3.0);
  EXPECT_EQ(hit->normal, vec3(0, 0, 1));
  EXPECT_TRUE(gi::intersect(gi::Ray{{0.5, 0.5, -3}, {0, 0, 1}}, tri)) << "both sides are hit";
}

TEST(Triangle, MissesOutsideTheEdges) {
  EXPECT_FALSE(gi::intersect(gi::Ray{{1.2, 1.2, 3}, {0, 0, -1}}, tri));   // beyond the hypotenuse
  EXPECT_FALSE(gi::intersect(gi::Ray{{-0.1, 0.5, 3}, {0, 0, -1}}, tri));  // left of the left edge
  EXPECT_TRUE(gi::intersect(gi::Ray{{1.0, 1.0, 3}, {0, 0, -1}}, tri));    // on the hypotenuse: closed
}

TEST(Triangle, RespectsTheRaysInterval) {
  EXPECT_FALSE(gi::intersect(gi::Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, 2.9}, tri));
  EXPECT_FALSE(gi::intersect(gi::Ray{{0.5, 0.5, 3}, {0, 0, 1}}, tri)) << "behind the origin";
  EXPECT_FALSE(gi::intersect(gi::Ray{{0.5, 0.5, 0}, {1, 0, 0}}, tri)) << "parallel, in its plane";
}

TEST(Triangle, DegenerateTrianglesAreRejected) {
  EXPECT_THROW(gi::check(gi::Triangle{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(gi::Triangle{{0, 0, 0}, {1, 0, 0}, {NAN, 0, 0}, 0}), std::invalid_argument);
  EXPECT_NO_THROW(gi::check(tri));
}
