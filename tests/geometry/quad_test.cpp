#include "gi/geometry/quad.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using gi::Quad;
using gi::Ray;
using gi::vec3;

namespace {
// A 2 x 1 parallelogram, sheared, in the plane z = 0, facing +z.
const Quad quad{{0, 0, 0}, {2, 0, 0}, {0.5, 1, 0}, 0};
}

TEST(Quad, AreaNormalAndCentre) {
  EXPECT_DOUBLE_EQ(gi::area(quad), 2.0);
  EXPECT_EQ(gi::normal(quad), vec3(0, 0, 1));
  EXPECT_EQ(gi::centre(quad), vec3(1.25, 0.5, 0));
}

TEST(Quad, HitInsideMissOutsideEvenWithinTheBoundingBox) {
  const auto hit = gi::intersect(Ray{{1.25, 0.5, 3}, {0, 0, -1}}, quad);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 3.0);
  EXPECT_EQ(hit->normal, vec3(0, 0, 1));
  // (0.1, 0.9) is inside the box [0, 2.5] x [0, 1] but left of the sheared edge.
  EXPECT_FALSE(gi::intersect(Ray{{0.1, 0.9, 3}, {0, 0, -1}}, quad));
  EXPECT_FALSE(gi::intersect(Ray{{2.4, 0.1, 3}, {0, 0, -1}}, quad));
}

TEST(Quad, ParallelRayMisses) { EXPECT_FALSE(gi::intersect(Ray{{1, 0.5, 1}, {1, 0, 0}}, quad)); }

TEST(Quad, DegenerateQuadsAreRejected) {
  EXPECT_THROW(gi::check(Quad{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Quad{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 0}), std::invalid_argument);
  EXPECT_NO_THROW(gi::check(quad));
}
