// Graded tests of exercise 4.1: a point on a parallelogram light. One point per test.
#include <gtest/gtest.h>

#include "gi/raytrace/soft_shadows.hpp"
#include "support/print.hpp"

using gi::vec2;
using gi::vec3;

namespace {
// Not axis-aligned, not square, edges not unit length.
const gi::QuadLight light{{{1, 4, -2}, {2, 0, 1}, {0.5, 0.5, -1.5}, 0}, gi::Color(1)};

void expect_point(const vec3& got, const vec3& want, const char* message) {
  EXPECT_NEAR(got.x, want.x, 1e-12) << message;
  EXPECT_NEAR(got.y, want.y, 1e-12) << message;
  EXPECT_NEAR(got.z, want.z, 1e-12) << message;
}
}  // namespace

TEST(Ex4_1_PointOnLight, OriginIsTheCorner) {
  expect_point(gi::point_on_light(light, {0, 0}), light.shape.corner, "(u, v) = (0, 0) is the light's corner");
}

TEST(Ex4_1_PointOnLight, UFollowsTheFirstEdgeAndVTheSecond) {
  expect_point(gi::point_on_light(light, {1, 0}), light.shape.corner + light.shape.edge_u,
               "(1, 0) is corner + edge_u: u moves along edge_u only");
  expect_point(gi::point_on_light(light, {0, 1}), light.shape.corner + light.shape.edge_v,
               "(0, 1) is corner + edge_v: v moves along edge_v only");
}

TEST(Ex4_1_PointOnLight, EdgesKeepTheirLength) {
  expect_point(gi::point_on_light(light, {1, 1}), light.shape.corner + light.shape.edge_u + light.shape.edge_v,
               "(1, 1) is the far corner: do not normalise the edges, their length is the light's size");
}

TEST(Ex4_1_PointOnLight, InteriorPointsAreAffine) {
  expect_point(gi::point_on_light(light, {0.25, 0.6}),
               light.shape.corner + 0.25 * light.shape.edge_u + 0.6 * light.shape.edge_v,
               "corner + u edge_u + v edge_v: linear in u and v, so uniform (u, v) are uniform over the area");
}
