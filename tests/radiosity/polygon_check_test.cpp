// Every Polygon is checked where it enters the library: a hand-built aggregate with a
// bad value gets one clear exception, never a crash or a NaN; two polygons that
// overlap in one plane are refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"

using gi::vec3;

namespace {

const double inf = std::numeric_limits<double>::infinity();

// The unit square in z = 0 facing +z, as a hand-built aggregate.
gi::Polygon unit_square() { return gi::Polygon{{vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}, {0, 0, 1}, {0.5, 0.5, 0}, 1.0}; }

// The message of the std::invalid_argument that `f` throws, or "" if it throws none.
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const gi::Polygon& bad, const std::string& words) {
  EXPECT_NE(message_of([&] { gi::check(bad); }).find(words), std::string::npos)
      << "check() must say '" << words << "', said '" << message_of([&] { gi::check(bad); }) << "'";
  // Every way in: the scene, a row's sender, the analytic pair, the point formula, the hemicube.
  const std::string scene = message_of([&] { gi::FormFactorScene({unit_square(), bad}); });
  EXPECT_NE(scene.find("polygon 1"), std::string::npos) << scene;
  const gi::FormFactorScene good({unit_square()});
  for (gi::FormFactorMethod method : {gi::FormFactorMethod::Differential, gi::FormFactorMethod::Analytic,
                                      gi::FormFactorMethod::MonteCarlo, gi::FormFactorMethod::Hemicube}) {
    gi::FormFactorSettings s;
    s.method = method;
    EXPECT_THROW(gi::form_factor_row(good, bad, 0, s), std::invalid_argument) << gi::name(method);
  }
  EXPECT_THROW(gi::form_factor_analytic_adaptive(unit_square(), bad), std::invalid_argument);
  EXPECT_THROW(gi::form_factor_analytic(bad, unit_square(), 4), std::invalid_argument);
  EXPECT_THROW(gi::form_factor_point_to_polygon({0.5, 0.5, -1}, {0, 0, 1}, bad), std::invalid_argument);
  gi::ItemBuffer buffer;
  EXPECT_THROW(gi::form_factor_row_hemicube({unit_square(), bad}, unit_square(), gi::hemicube_weights(10), buffer),
               std::invalid_argument);
  EXPECT_THROW(gi::render_item_buffer({unit_square(), bad}, {0.5, 0.5, 0}, {0, 0, 1}, 10, buffer),
               std::invalid_argument);
  EXPECT_THROW(gi::form_factor_matrix_hemicube({unit_square(), bad}, 10, 1), std::invalid_argument);
}

}  // namespace

TEST(PolygonCheck, AHandBuiltSquareIsAccepted) {
  EXPECT_NO_THROW(gi::check(unit_square()));
  EXPECT_NO_THROW(gi::FormFactorScene({unit_square()}));
}

TEST(PolygonCheck, NonFiniteValuesAreRefusedEverywhere) {
  gi::Polygon p = unit_square();
  p.corners[2].x = inf;  // once a SIGSEGV in the BVH builder
  expect_refused(p, "corner 2 is not finite");
  p = unit_square();
  p.corners[0].y = NAN;
  expect_refused(p, "corner 0 is not finite");
  p = unit_square();
  p.normal = vec3(NAN);
  expect_refused(p, "unit vector");
  p = unit_square();
  p.centre.z = inf;
  expect_refused(p, "centre");
  p = unit_square();
  p.area = NAN;
  expect_refused(p, "area");
}

TEST(PolygonCheck, ShapesThatAreNotFlatConvexQuadrilateralsAreRefused) {
  gi::Polygon p = unit_square();
  p.corners = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 0, 0), vec3(3, 0, 0)};
  expect_refused(p, "span no area");
  p = unit_square();
  p.corners[2].z = 0.1;  // the mean plane 1.8% of the diagonal off corner 2; 1% is allowed
  expect_refused(p, "not in one plane");
  p = unit_square();
  p.corners[2] = vec3(0.3, 0.3, 0);  // a dart
  expect_refused(p, "convex");
  p = unit_square();
  std::swap(p.corners[1], p.corners[3]);  // clockwise about the normal
  expect_refused(p, "clockwise");
}

TEST(PolygonCheck, FieldsThatDisagreeWithTheCornersAreRefused) {
  gi::Polygon p = unit_square();
  p.area = 0;
  expect_refused(p, "area 0 is not the corners' 1");
  p = unit_square();
  p.area = 2;
  expect_refused(p, "area 2");
  p = unit_square();
  p.normal = vec3(0, 0, 2);
  expect_refused(p, "unit vector");
  p = unit_square();
  p.normal = vec3(0, 0, -1);
  expect_refused(p, "clockwise");
  p = unit_square();
  p.centre = vec3(1.5, 0.5, 0);
  expect_refused(p, "centre");
}

TEST(PolygonCheck, TheCentreOfASlightlyTwistedQuadIsLiftedAboveAllOfIt) {
  // Corners 1 and 3 raised by 0.5% of the side: make_polygon takes it (the Cornell
  // box's red wall is like this), and nothing of it rises above the lifted centre.
  const gi::Polygon p = gi::make_polygon({vec3(0, 0, 0), vec3(1, 0, 0.005), vec3(1, 1, 0), vec3(0, 1, 0.005)});
  EXPECT_EQ(p.normal, vec3(0, 0, 1));
  EXPECT_NEAR(gi::lift(p), 0.005 - p.centre.z, 1e-15) << "the highest corners above the centre";
  EXPECT_GT(gi::lift(p), 0.003);
  const vec3 top = gi::lifted_centre(p);
  for (const vec3& c : p.corners) EXPECT_LE(gi::dot(c - top, p.normal), 1e-15);
  EXPECT_EQ(gi::lift(unit_square()), 0.0) << "a flat polygon is not lifted";
}

TEST(PolygonCheck, OverlappingPolygonsAreRefusedByName) {
  // The same square twice, back to back, half covered, and merely sharing an edge.
  const gi::Polygon square = unit_square();
  const gi::Polygon back = gi::make_polygon({vec3(0, 0, 0), vec3(0, 1, 0), vec3(1, 1, 0), vec3(1, 0, 0)});
  const gi::Polygon half = gi::make_polygon({vec3(-0.5, 0, 0), vec3(0.5, 0, 0), vec3(0.5, 1, 0), vec3(-0.5, 1, 0)});
  const gi::Polygon beside = gi::make_polygon({vec3(1, 0, 0), vec3(2, 0, 0), vec3(2, 1, 0), vec3(1, 1, 0)});
  const gi::Polygon above = gi::make_polygon({vec3(0, 0, 1e-3), vec3(1, 0, 1e-3), vec3(1, 1, 1e-3), vec3(0, 1, 1e-3)});
  for (const gi::Polygon& other : {square, back, half}) {
    const std::string what = message_of([&] { gi::FormFactorScene({beside, square, other}); });
    EXPECT_NE(what.find("polygons 1 and 2"), std::string::npos) << what;
    EXPECT_NE(what.find("overlap"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(gi::FormFactorScene({square, beside, above})) << "an edge shared, or a gap of 1e-3, is fine";
  const gi::Polygon hair = gi::make_polygon({vec3(0, 0, 1e-14), vec3(0, 1, 1e-14), vec3(1, 1, 1e-14), vec3(1, 0, 1e-14)});
  EXPECT_THROW(gi::FormFactorScene({square, hair}), std::invalid_argument) << "1e-14 apart is coincident";
  // A mesh names the surfaces.
  const gi::Surface floor{"floor", square.corners, gi::Color(0.5)}, rug{"rug", half.corners, gi::Color(0.5)};
  const std::string what = message_of([&] { gi::make_mesh({floor, rug}, {1.0, 1}); });
  EXPECT_NE(what.find("'floor' and 'rug'"), std::string::npos) << what;
}

TEST(PolygonCheck, BadSettingsAreRefused) {
  gi::FormFactorSettings s;
  s.tolerance = 0;
  EXPECT_THROW(gi::check(s), std::invalid_argument);
  s.tolerance = NAN;
  EXPECT_THROW(gi::check(s), std::invalid_argument);
  EXPECT_THROW(gi::form_factor_analytic_adaptive(unit_square(), unit_square(), 1.0), std::invalid_argument);
  EXPECT_THROW(gi::form_factor_point_to_polygon({NAN, 0, 1}, {0, 0, 1}, unit_square()), std::invalid_argument);
}
