// Graded tests of exercise 4.1: a point on a parallelogram light. One point per test.
#include <gtest/gtest.h>

#include <string>

#include "gi/raytrace/soft_shadows.hpp"
#include "support/print.hpp"

using gi::vec2;
using gi::vec3;

namespace {
// Not axis-aligned, not square, edges not unit length.
const gi::QuadLight light{{{1, 4, -2}, {2, 0, 1}, {0.5, 0.5, -1.5}, 0}, gi::Color(1)};

// The slip a wrong point matches, named first, or the test's own message.
std::string diagnosis(const vec3& got, vec2 uv, const char* message) {
  const gi::Quad& q = light.shape;
  const auto is = [&](const vec3& p) { return gi::length(got - p) < 1e-9; };
  if (!(uv.x == 0.5 && uv.y == 0.5) && is(q.corner + 0.5 * q.edge_u + 0.5 * q.edge_v))
    return "every (u, v) gives the light's centre: the point is corner + u edge_u + v edge_v, so that the samples "
           "spread over the whole light (one point at the centre is a point light: hard shadows)";
  if (!(uv.x == uv.y) && is(q.corner + uv.y * q.edge_u + uv.x * q.edge_v))
    return "u and v are swapped: u moves along edge_u, v along edge_v";
  if (is(q.corner + (uv.x - 0.5) * q.edge_u + (uv.y - 0.5) * q.edge_v))
    return "the corner is not the centre: (u, v) in [0, 1]^2 runs from the corner, corner + u edge_u + v edge_v";
  return message;
}

void expect_point(const vec3& got, vec2 uv, const vec3& want, const char* message) {
  const std::string why = diagnosis(got, uv, message);
  EXPECT_NEAR(got.x, want.x, 1e-12) << why;
  EXPECT_NEAR(got.y, want.y, 1e-12) << why;
  EXPECT_NEAR(got.z, want.z, 1e-12) << why;
}
}  // namespace

TEST(Ex4_1_PointOnLight, OriginIsTheCorner) {
  expect_point(gi::point_on_light(light, {0, 0}), {0, 0}, light.shape.corner, "(u, v) = (0, 0) is the light's corner");
}

TEST(Ex4_1_PointOnLight, UFollowsTheFirstEdgeAndVTheSecond) {
  expect_point(gi::point_on_light(light, {1, 0}), {1, 0}, light.shape.corner + light.shape.edge_u,
               "(1, 0) is corner + edge_u: u moves along edge_u only");
  expect_point(gi::point_on_light(light, {0, 1}), {0, 1}, light.shape.corner + light.shape.edge_v,
               "(0, 1) is corner + edge_v: v moves along edge_v only");
}

TEST(Ex4_1_PointOnLight, EdgesKeepTheirLength) {
  expect_point(gi::point_on_light(light, {1, 1}), {1, 1}, light.shape.corner + light.shape.edge_u + light.shape.edge_v,
               "(1, 1) is the far corner: do not normalise the edges, their length is the light's size");
}

TEST(Ex4_1_PointOnLight, InteriorPointsAreAffine) {
  expect_point(gi::point_on_light(light, {0.25, 0.6}), {0.25, 0.6},
               light.shape.corner + 0.25 * light.shape.edge_u + 0.6 * light.shape.edge_v,
               "corner + u edge_u + v edge_v: linear in u and v, so uniform (u, v) are uniform over the area");
}
