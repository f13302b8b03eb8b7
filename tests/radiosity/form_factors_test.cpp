#include <gtest/gtest.h>

#include <cmath>

#include "gi/radiosity/configuration_factors.hpp"
#include "gi/radiosity/form_factor_formulas.hpp"
#include "gi/radiosity/form_factor_hemicube.hpp"
#include "gi/radiosity/mesh.hpp"
#include "gi/radiosity/radiosity_scenes.hpp"

using gi::vec3;

namespace {

std::vector<gi::Polygon> polygons_of(const gi::RadiosityScene& scene) {
  std::vector<gi::Polygon> out;
  for (const gi::Surface& s : scene.surfaces) out.push_back(gi::make_polygon(s.corners));
  return out;
}

double hemicube(const std::vector<gi::Polygon>& polygons, int from, int to, int resolution) {
  gi::ItemBuffer buffer;
  return gi::form_factor_row_hemicube(polygons, polygons[from], gi::hemicube_weights(resolution), buffer)[to];
}

}  // namespace

TEST(Hemicube, DeltaFormFactorsSumToOne) {
  for (int res : {10, 50, 100, 200}) {
    const gi::HemicubeWeights w = gi::hemicube_weights(res);
    EXPECT_NEAR(w.sum(), 1.0, 2.0 / (res * res)) << res;  // midpoint rule: O(h^2)
  }
  EXPECT_THROW(gi::hemicube_weights(51), std::invalid_argument);
  EXPECT_THROW(gi::hemicube_weights(0), std::invalid_argument);
}

TEST(Hemicube, ProjectionFindsFaceAndCell) {
  auto cell = gi::project_to_hemicube({0, 0, 1}, 100);
  ASSERT_TRUE(cell);
  EXPECT_EQ(cell->face, gi::HemicubeFace::Top);
  EXPECT_EQ(cell->column, 50);
  EXPECT_EQ(cell->row, 50);
  cell = gi::project_to_hemicube({2, -1, 1}, 100);  // on the face x = 1 at y = -0.5, z = 0.5
  ASSERT_TRUE(cell);
  EXPECT_EQ(cell->face, gi::HemicubeFace::PlusX);
  EXPECT_EQ(cell->column, 25);
  EXPECT_EQ(cell->row, 25);
  cell = gi::project_to_hemicube({0.3, -4, 0.1}, 10);
  ASSERT_TRUE(cell);
  EXPECT_EQ(cell->face, gi::HemicubeFace::MinusY);
  EXPECT_FALSE(gi::project_to_hemicube({1, 0, -0.1}, 10));
}

TEST(FormFactors, DifferentialMatchesTheFarFieldAndFailsUpClose) {
  // Two unit squares facing each other: the point formula is good far apart, and
  // exceeds 1 when they are close -- the lecture's warning.
  for (double c : {10.0, 0.2}) {
    const auto p = polygons_of(gi::parallel_squares(1.0, c));
    const double point = gi::form_factor_differential(p[0].centre, p[0].normal, p[1].centre, p[1].normal, 1.0, 1.0);
    const double exact = gi::ff_parallel_rectangles(1, 1, c);
    if (c > 1)
      EXPECT_NEAR(point, exact, 0.01 * exact);
    else
      EXPECT_GT(point, 1.0);
  }
}

TEST(FormFactors, ContourIntegralIsExactForAPointUnderACorner) {
  // Point at the origin facing +z, rectangle [0, a] x [0, b] at height c facing down.
  const double a = 1.3, b = 0.6, c = 0.9;
  const gi::Polygon rectangle = gi::make_polygon({vec3(0, 0, c), vec3(0, b, c), vec3(a, b, c), vec3(a, 0, c)});
  EXPECT_NEAR(gi::form_factor_point_to_polygon({0, 0, 0}, {0, 0, 1}, rectangle),
              gi::ff_point_to_parallel_rectangle_corner(a, b, c), 1e-12);
  // Seen from behind: nothing.
  EXPECT_EQ(gi::form_factor_point_to_polygon({0, 0, 2}, {0, 0, -1}, rectangle), 0.0);
}

TEST(FormFactors, AnalyticPatchToPatchConvergesToTheClosedForms) {
  const auto par = polygons_of(gi::parallel_squares(1.0, 1.0));
  EXPECT_NEAR(gi::form_factor_analytic(par[0], par[1], 10), gi::ff_parallel_rectangles(1, 1, 1), 1e-11);
  const auto per = polygons_of(gi::perpendicular_squares(1.0));
  // The shared edge makes the integrand singular: Gauss converges, but slowly.
  const double exact = gi::ff_perpendicular_rectangles(1, 1, 1);
  EXPECT_NEAR(gi::form_factor_analytic(per[0], per[1], 16), exact, 2e-3);
  EXPECT_LT(std::abs(gi::form_factor_analytic(per[0], per[1], 16) - exact),
            std::abs(gi::form_factor_analytic(per[0], per[1], 4) - exact));
}

TEST(FormFactors, HemicubeAgreesWithTheClosedFormsAtResolution100) {
  // The hemicube stands at the sender's centre, so it gives the point-to-patch factor;
  // on whole patches that is the method's own error, compared here with the
  // contour integral from the same point.
  const auto par = polygons_of(gi::parallel_squares(1.0, 1.0));
  const double point = gi::form_factor_point_to_polygon(par[0].centre, par[0].normal, par[1]);
  EXPECT_NEAR(hemicube(par, 0, 1, 100), point, 1e-2 * point);
  // Finely meshed, the element rows average to the patch-to-patch factor.
  const gi::Mesh mesh = gi::make_mesh(gi::perpendicular_squares(1.0).surfaces, {1.0, 8});
  const std::vector<gi::Polygon> elements = gi::element_shapes(mesh);
  gi::ItemBuffer buffer;
  const gi::HemicubeWeights w = gi::hemicube_weights(100);
  double f = 0;
  for (int i = 0; i < 64; ++i) {  // floor elements to every wall element
    const std::vector<double> row = gi::form_factor_row_hemicube(elements, elements[i], w, buffer);
    for (int j = 64; j < 128; ++j) f += row[j] / 64;
  }
  EXPECT_NEAR(f, gi::ff_perpendicular_rectangles(1, 1, 1), 1e-2);
}

TEST(FormFactors, HemicubeRowsSumToOneInAClosedBoxAndLessInAnOpenOne) {
  const gi::Mesh closed = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 2});
  const gi::Mesh open = gi::make_mesh(gi::open_box(1.0).surfaces, {0.5, 2});
  const gi::HemicubeWeights w = gi::hemicube_weights(100);
  gi::ItemBuffer buffer;
  for (const gi::Mesh* mesh : {&closed, &open}) {
    const std::vector<gi::Polygon> elements = gi::element_shapes(*mesh);
    double lowest = 2, highest = 0;
    for (const gi::Polygon& from : elements) {
      const std::vector<double> row = gi::form_factor_row_hemicube(elements, from, w, buffer);
      double sum = 0;
      for (double f : row) sum += f;
      lowest = std::min(lowest, sum), highest = std::max(highest, sum);
    }
    if (mesh == &closed) {
      EXPECT_NEAR(lowest, 1.0, 1e-3);
      EXPECT_NEAR(highest, 1.0, 1e-3);
    } else {
      EXPECT_LT(highest, 0.99);
      EXPECT_GT(lowest, 0.3);
    }
  }
}

TEST(FormFactors, HemicubeSeesTheBlocker) {
  const auto occluded = polygons_of(gi::occluded_squares(1.0, 2.0));
  const auto open = polygons_of(gi::parallel_squares(1.0, 2.0));
  const double seen = hemicube(occluded, 0, 1, 200), unblocked = hemicube(open, 0, 1, 200);
  EXPECT_LT(seen, 0.5 * unblocked);       // the blocker hides the middle of the view
  EXPECT_NEAR(hemicube(occluded, 0, 3, 200), 0.0, 1e-12);  // its top faces away from the bottom
  EXPECT_GT(hemicube(occluded, 0, 2, 200), 0.0);            // its underside is what the bottom sees
}
