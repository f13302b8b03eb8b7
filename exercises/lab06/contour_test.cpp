// Graded tests of exercise 6.2: Lambert's contour integral. One point per test.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "support/print.hpp"

using gi::vec3;

namespace {
// Counter-clockwise seen from below (from the point at the origin): the rectangle
// [x0, x1] x [y0, y1] at height c, facing down.
std::array<vec3, 4> rectangle(double x0, double x1, double y0, double y1, double c) {
  return {vec3(x0, y0, c), vec3(x0, y1, c), vec3(x1, y1, c), vec3(x1, y0, c)};
}
double contour(const vec3& n, const std::array<vec3, 4>& v) { return gi::contour_integral({0, 0, 0}, n, v.data(), 4); }
}  // namespace

TEST(Ex6_2_Contour, CornerRectangleMatchesHowell) {
  const double exact = gi::ff_point_to_parallel_rectangle_corner(1.3, 0.6, 0.9);
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(0, 1.3, 0, 0.6, 0.9)), exact, 1e-12)
      << "F = 1/(2 pi) sum gamma_k n . unit(R_k+1 x R_k); a negative value means the cross product is the "
         "wrong way round, a value 2 pi too large a missing 1/(2 pi)";
}

TEST(Ex6_2_Contour, ThePointNeedNotBeAtTheOrigin) {
  // Howell's corner case moved, point and rectangle together, to x = (2.5, -1.5, 0.75):
  // the same form factor. With x at the origin a forgotten "- x" on any vertex hides.
  const vec3 x(2.5, -1.5, 0.75);
  std::array<vec3, 4> r = rectangle(0, 1.3, 0, 0.6, 0.9);
  for (vec3& v : r) v += x;
  EXPECT_NEAR(gi::contour_integral(x, {0, 0, 1}, r.data(), 4), gi::ff_point_to_parallel_rectangle_corner(1.3, 0.6, 0.9),
              1e-12)
      << "the vertex vectors are R_k = v_k - x for every vertex, the next one of each edge included: a point at "
         "the origin hides a forgotten '- x'";
}

TEST(Ex6_2_Contour, CentredSquareIsFourCorners) {
  const double corner = gi::ff_point_to_parallel_rectangle_corner(1, 1, 2);
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(-1, 1, -1, 1, 2)), 4 * corner, 1e-12)
      << "a square centred over the point is four of Howell's corner rectangles";
}

TEST(Ex6_2_Contour, GammaIsTheAngleBetweenTheVertexVectors) {
  // A thin sliver far off-axis: wrong angles (e.g. not normalising before acos) show here.
  const double a = gi::ff_point_to_parallel_rectangle_corner(3.0, 2.5, 1.0);
  const double b = gi::ff_point_to_parallel_rectangle_corner(2.9, 2.5, 1.0);
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(2.9, 3.0, 0, 2.5, 1.0)), a - b, 1e-12)
      << "gamma_k is the angle between R_k and R_k+1: atan2(|R_k+1 x R_k|, R_k . R_k+1)";
}

TEST(Ex6_2_Contour, AnglesBeyondNinetyDegrees) {
  // The strip [-3, 3] x [0.5, 1] at height 1: its long near edge subtends 139 degrees.
  const double exact = 2 * (gi::ff_point_to_parallel_rectangle_corner(3, 1, 1) -
                            gi::ff_point_to_parallel_rectangle_corner(3, 0.5, 1));
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(-3, 3, 0.5, 1, 1)), exact, 1e-12)
      << "an edge can subtend more than 90 degrees: asin of the sine cannot tell 41 degrees from 139; "
         "atan2(|R_k+1 x R_k|, R_k . R_k+1) gets every angle in [0, 180]";
}

TEST(Ex6_2_Contour, SmallPolygonFarAway) {
  // A 1 cm square 10 m away: F = 3.2e-7. Howell's formula has no cancellation here,
  // so it is exact to a few units of round-off.
  const double exact = gi::ff_point_to_parallel_rectangle_corner(0.01, 0.01, 10);
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(0, 0.01, 0, 0.01, 10)), exact, 1e-12 * exact)
      << "relative error above 1e-12 on a small, distant polygon: its edges subtend tiny angles, and acos(cos "
         "gamma) near cos gamma = 1 keeps only the square root of the digits (1e-10 relative here); "
         "atan2(|R_k+1 x R_k|, R_k . R_k+1) keeps them all";
}

TEST(Ex6_2_Contour, WorksForTriangles) {
  // The square split along its diagonal: the two halves add up to the square. Each
  // triangle sits in an array of four whose last entry is not one of its vertices.
  const std::array<vec3, 4> q = rectangle(0, 1, 0, 1, 1);
  const vec3 decoy(40, -30, 1);
  const std::array<vec3, 4> t1 = {q[0], q[1], q[2], decoy}, t2 = {q[0], q[2], q[3], decoy};
  const double whole = gi::ff_point_to_parallel_rectangle_corner(1, 1, 1);
  EXPECT_NEAR(gi::contour_integral({0, 0, 0}, {0, 0, 1}, t1.data(), 3) +
                  gi::contour_integral({0, 0, 0}, {0, 0, 1}, t2.data(), 3),
              whole, 1e-12)
      << "use `count` vertices (here 3) and wrap around from the last to the first";
}

TEST(Ex6_2_Contour, TurningTheWholeSceneChangesNothing) {
  // Howell's corner case turned 40 degrees about x and then 25 about y: the point's
  // normal is no longer the z axis, the form factor is the same.
  const double a = 40 * gi::pi / 180, b = 25 * gi::pi / 180;
  const auto turn = [&](vec3 v) {
    v = vec3(v.x, std::cos(a) * v.y - std::sin(a) * v.z, std::sin(a) * v.y + std::cos(a) * v.z);
    return vec3(std::cos(b) * v.x + std::sin(b) * v.z, v.y, -std::sin(b) * v.x + std::cos(b) * v.z);
  };
  std::array<vec3, 4> r = rectangle(0, 1.3, 0, 0.6, 0.9);
  for (vec3& v : r) v = turn(v);
  EXPECT_NEAR(contour(turn({0, 0, 1}), r), gi::ff_point_to_parallel_rectangle_corner(1.3, 0.6, 0.9), 1e-12)
      << "project each edge's term on the point's normal n (n . (R_k+1 x R_k)), not on a fixed axis";
}

TEST(Ex6_2_Contour, TheNormalOfTheReceivingPointCounts) {
  // A huge polygon over the half x > 0 of the plane z = 1, seen from a point whose
  // normal is +x: it fills half of the point's hemisphere, F -> 1/2.
  const double L = 1e5;
  EXPECT_NEAR(contour({1, 0, 0}, rectangle(0, L, -L, L, 1)), 0.5, 1e-4)
      << "project each edge's term on the point's normal n, not on the z axis";
}

TEST(Ex6_2_Contour, CoversTheWholeHemisphere) {
  const double L = 1e5;
  EXPECT_NEAR(contour({0, 0, 1}, rectangle(-L, L, -L, L, 1)), 1.0, 1e-4)
      << "an infinite plane above the point fills its view: F = 1";
}
