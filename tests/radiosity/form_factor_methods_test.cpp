#include "gi/radiosity/form_factors/form_factors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace {

gi::FormFactorScene scene_of(const gi::RadiosityScene& s) {
  std::vector<gi::Polygon> polygons;
  for (const gi::Surface& surface : s.surfaces) polygons.push_back(gi::make_polygon(surface.corners));
  return gi::FormFactorScene(polygons);
}

double f(const gi::FormFactorScene& scene, int i, int j, gi::FormFactorSettings settings) {
  return gi::form_factor_row(scene, scene.polygons()[i], i, settings)[j];
}

gi::FormFactorSettings with(gi::FormFactorMethod method) {
  gi::FormFactorSettings s;
  s.method = method;
  return s;
}

}  // namespace

TEST(FormFactorMethods, MonteCarloIsUnbiasedForPatchToPatch) {
  // Area-averaged: converges to the closed form, within 4 standard errors.
  gi::FormFactorSettings s = with(gi::FormFactorMethod::MonteCarlo);
  s.rays = 200000;
  const double exact_par = gi::ff_parallel_rectangles(1, 1, 1), exact_per = gi::ff_perpendicular_rectangles(1, 1, 1);
  EXPECT_NEAR(f(scene_of(gi::parallel_squares(1, 1)), 0, 1, s), exact_par, 4 * std::sqrt(exact_par / s.rays));
  EXPECT_NEAR(f(scene_of(gi::perpendicular_squares(1)), 0, 1, s), exact_per, 4 * std::sqrt(exact_per / s.rays));
}

TEST(FormFactorMethods, AnalyticIsExactWithoutOcclusion) {
  gi::FormFactorSettings s = with(gi::FormFactorMethod::Analytic);
  s.quadrature_order = 10;
  EXPECT_NEAR(f(scene_of(gi::parallel_squares(1, 1)), 0, 1, s), gi::ff_parallel_rectangles(1, 1, 1), 1e-11);
}

TEST(FormFactorMethods, PointMethodsGiveTheFactorFromTheCentre) {
  // The hemicube and the differential formula look from the sender's centre: compare
  // them with the contour integral from that point, not with the patch average.
  const gi::FormFactorScene scene = scene_of(gi::parallel_squares(1, 1));
  const gi::Polygon& from = scene.polygons()[0];
  const double point = gi::form_factor_point_to_polygon(from.centre, from.normal, scene.polygons()[1]);
  EXPECT_NEAR(f(scene, 0, 1, with(gi::FormFactorMethod::Hemicube)), point, 2e-3 * point);
  EXPECT_GT(point, 1.15 * gi::ff_parallel_rectangles(1, 1, 1)) << "the near-field error of point methods";
  const gi::FormFactorScene far = scene_of(gi::parallel_squares(1, 10));
  EXPECT_NEAR(f(far, 0, 1, with(gi::FormFactorMethod::Differential)), gi::ff_parallel_rectangles(1, 1, 10),
              0.01 * gi::ff_parallel_rectangles(1, 1, 10));
}

TEST(FormFactorMethods, OcclusionIsSeenByRaysAndHemicubesNotByTheContourIntegral) {
  const gi::FormFactorScene blocked = scene_of(gi::occluded_squares(1, 2)), open = scene_of(gi::parallel_squares(1, 2));
  EXPECT_EQ(f(blocked, 0, 1, with(gi::FormFactorMethod::Differential)), 0.0) << "the centres' line is blocked";
  gi::FormFactorSettings mc = with(gi::FormFactorMethod::MonteCarlo);
  mc.rays = 40000;
  const double seen = f(blocked, 0, 1, mc), unblocked = f(open, 0, 1, mc);
  EXPECT_GT(seen, 0.2 * unblocked);
  EXPECT_LT(seen, 0.8 * unblocked);
  EXPECT_DOUBLE_EQ(f(blocked, 0, 1, with(gi::FormFactorMethod::Analytic)),
                   f(open, 0, 1, with(gi::FormFactorMethod::Analytic)));
}

TEST(FormFactorMethods, RowsOfAClosedBoxSumToOne) {
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 1});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  gi::FormFactorSettings mc = with(gi::FormFactorMethod::MonteCarlo);
  mc.rays = 4096;
  for (const gi::FormFactorSettings& s : {mc, with(gi::FormFactorMethod::Hemicube)}) {
    const gi::FormFactorMatrix F = gi::form_factor_matrix(scene, s, 2);
    for (double sum : gi::row_sums(F)) EXPECT_NEAR(sum, 1.0, 2e-3) << gi::name(s.method);
  }
}

TEST(FormFactorMethods, MatricesAreTheSameForAnyThreadCount) {
  const gi::Mesh mesh = gi::make_mesh(gi::cornell_box().surfaces, {200.0, 1});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  gi::FormFactorSettings mc = with(gi::FormFactorMethod::MonteCarlo);
  mc.rays = 300;
  EXPECT_EQ(gi::form_factor_matrix(scene, mc, 1).values, gi::form_factor_matrix(scene, mc, 3).values);
}

TEST(FormFactorMethods, FirstHitAndVisibility) {
  const gi::FormFactorScene scene = scene_of(gi::occluded_squares(1, 2));
  const auto up = scene.first_hit(gi::Ray{{0, 0.1, 0}, {0, 1, 0}});
  ASSERT_TRUE(up);
  EXPECT_EQ(up->polygon, 2) << "the blocker's underside";
  EXPECT_TRUE(up->front);
  const auto down = scene.first_hit(gi::Ray{{0, 1.9, 0}, {0, -1, 0}});
  ASSERT_TRUE(down);
  EXPECT_EQ(down->polygon, 3);
  EXPECT_FALSE(scene.visible({0, 0, 0}, {0, 2, 0}));
  EXPECT_TRUE(scene.visible({0.45, 0, 0.45}, {0.45, 2, 0.45}));
  EXPECT_THROW(gi::form_factor_method_from_name("radiosity"), std::invalid_argument);
  gi::FormFactorSettings bad;
  bad.hemicube_resolution = 33;
  EXPECT_THROW(gi::check(bad), std::invalid_argument);
}

TEST(FormFactorMethods, AnalyticMatrixIsReciprocalAndFlatPatchesSeeNothingOfThemselves) {
  // Two facing squares cut into elements of different sizes (3 x 3 and 4 x 4), so
  // reciprocity is not symmetry: A_i F_ij = A_j F_ji to quadrature accuracy. (Pairs that
  // share an edge, like the Cornell floor and a block, converge far more slowly: their
  // integrand is singular along the edge.)
  gi::RadiosityScene pair = gi::parallel_squares(1.0, 0.5);
  std::vector<gi::Polygon> polygons;
  for (int s = 0; s < 2; ++s) {
    const gi::Mesh mesh = gi::make_mesh({pair.surfaces[s]}, {1.0, s == 0 ? 3 : 4});
    for (const gi::Polygon& p : gi::element_shapes(mesh)) polygons.push_back(p);
  }
  const gi::FormFactorScene scene(polygons);
  gi::FormFactorSettings analytic = with(gi::FormFactorMethod::Analytic);
  analytic.quadrature_order = 8;
  const gi::FormFactorMatrix F = gi::form_factor_matrix(scene, analytic, 2);
  std::vector<double> areas;
  for (const gi::Polygon& p : polygons) areas.push_back(p.area);
  EXPECT_LT(gi::reciprocity_error(F, areas), 1e-6);
  // Coplanar elements and each element itself: F = 0, for every method (the hemicube
  // sees up to 1e-7 of a neighbour on the red wall, which is twisted by 3 mm).
  const gi::Mesh cornell = gi::make_mesh(gi::cornell_box().surfaces, {300.0, 1});
  const gi::FormFactorScene box(gi::element_shapes(cornell));
  for (const gi::FormFactorSettings& s : {analytic, with(gi::FormFactorMethod::Hemicube)}) {
    const gi::FormFactorMatrix M = gi::form_factor_matrix(box, s, 2);
    for (int i = 0; i < M.n; ++i)
      for (int j = 0; j < M.n; ++j)
        if (cornell.elements[i].surface == cornell.elements[j].surface) {
          ASSERT_LT(M(i, j), 1e-6) << gi::name(s.method) << " " << i << " " << j;
        }
  }
}

TEST(FormFactorMethods, SymmetricScenesGiveSymmetricRows) {
  // From the floor's centre of a closed cube, the four walls are alike.
  const gi::FormFactorScene scene = scene_of(gi::closed_box(1.0));
  for (const gi::FormFactorSettings& s : {with(gi::FormFactorMethod::Hemicube), with(gi::FormFactorMethod::Analytic)}) {
    const std::vector<double> row = gi::form_factor_row(scene, scene.polygons()[0], 0, s);
    for (int wall = 3; wall < 6; ++wall) EXPECT_NEAR(row[wall], row[2], 2e-3) << gi::name(s.method);
    EXPECT_NEAR(std::accumulate(row.begin(), row.end(), 0.0), 1.0, 2e-3) << gi::name(s.method);
  }
}
