// No NaN leaves a form-factor routine: every method, from every polygon of scenes that
// are degenerate (refused with an exception), near-coincident, far, tiny, huge, twisted
// or crossing, gives a finite row of non-negative values summing to at most 1 (up to
// each method's own precision), and F_ii = 0. The differential formula alone would
// give 3e21 for squares 1e-11 apart: its rows are scaled to 1 where they exceed it.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"

using gi::vec3;

namespace {

gi::Polygon quad(vec3 o, vec3 u, vec3 v) { return gi::make_polygon({o, o + u, o + u + v, o + v}); }

// A unit-ish square at height z facing down, and the unit square at 0 facing up, scaled.
std::vector<gi::Polygon> facing(double gap, double size = 1, double shift = 0) {
  return {quad({0, 0, 0}, {size, 0, 0}, {0, size, 0}), quad({shift, 0, gap}, {0, size, 0}, {size, 0, 0})};
}

struct Case {
  std::string name;
  std::vector<gi::Polygon> polygons;
};

std::vector<Case> cases() {
  std::vector<Case> list;
  for (double gap : {1e-11, 1e-9, 1e-6, 1e-3}) list.push_back({"facing, gap " + std::to_string(gap), facing(gap)});
  list.push_back({"half over, gap 1e-9", facing(1e-9, 1, 0.5)});
  for (double gap : {1e6, 1e12}) list.push_back({"facing, gap " + std::to_string(gap), facing(gap)});
  list.push_back({"tiny and far", facing(1e3, 1e-6)});
  list.push_back({"huge and near", facing(1, 1e6)});
  list.push_back({"perpendicular, shared edge", {quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({0, 0, 0}, {0, 0, 1}, {1, 0, 0})}});
  list.push_back({"perpendicular, shared corner", {quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({1, 0, 0}, {0, 0, 1}, {1, 0, 0})}});
  list.push_back({"T: an edge on the other's middle", {quad({-1, 0, 0}, {2, 0, 0}, {0, 1, 0}), quad({-0.5, 0.5, 0}, {0, 0, 1}, {1, 0, 0})}});
  list.push_back({"crossing through each other", {quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}), quad({-0.5, 0, -0.5}, {0, 0, 1}, {1, 0, 0})}});
  list.push_back({"coplanar neighbours", {quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), quad({1, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                                          quad({0, 1, 0}, {1, 0, 0}, {0, 1, 0})}});
  list.push_back({"twisted, facing",
                  {gi::make_polygon({vec3(0, 0, 0), vec3(1, 0, 0.01), vec3(1, 1, 0), vec3(0, 1, 0.01)}),
                   gi::make_polygon({vec3(0, 0, 0.3), vec3(0, 1, 0.29), vec3(1, 1, 0.3), vec3(1, 0, 0.29)})}});
  list.push_back({"slivers", {quad({0, 0, 0}, {1, 0, 0}, {0, 1e-9, 0}), quad({0, 0, 1e-9}, {0, 1e-9, 0}, {1, 0, 0})}});
  return list;
}

}  // namespace

TEST(NanSweep, EveryMethodGivesFiniteRowsSummingToAtMostOne) {
  for (const Case& c : cases()) {
    const gi::FormFactorScene scene(c.polygons);
    for (gi::FormFactorMethod method : {gi::FormFactorMethod::Differential, gi::FormFactorMethod::Analytic,
                                        gi::FormFactorMethod::MonteCarlo, gi::FormFactorMethod::Hemicube}) {
      gi::FormFactorSettings settings;
      settings.method = method;
      settings.rays = 999;
      const gi::FormFactorMatrix F = gi::form_factor_matrix(scene, settings, 1);
      for (int i = 0; i < F.n; ++i) {
        double sum = 0;
        for (int j = 0; j < F.n; ++j) {
          ASSERT_TRUE(std::isfinite(F(i, j)) && F(i, j) >= 0) << c.name << ", " << gi::name(method) << ": F(" << i
                                                                << ", " << j << ") = " << F(i, j);
          sum += F(i, j);
        }
        EXPECT_EQ(F(i, i), 0.0) << c.name << ", " << gi::name(method);
        EXPECT_LE(sum, 1 + 1e-9) << c.name << ", " << gi::name(method) << ", row " << i;
      }
    }
  }
}

TEST(NanSweep, DegenerateInputIsRefusedWithAnExceptionNotANaN) {
  const gi::Polygon square = quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const std::vector<std::array<vec3, 4>> bad = {
      {vec3(0), vec3(1, 0, 0), vec3(2, 0, 0), vec3(3, 0, 0)},                // on a line
      {vec3(0), vec3(0), vec3(0), vec3(0)},                                  // a point
      {vec3(0), vec3(1, 0, 0), vec3(1, 1e-300, 0), vec3(0, 1e-300, 0)},      // no area to speak of
      {vec3(0), vec3(INFINITY, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)},         // infinite
      {vec3(0), vec3(1, 0, 0), vec3(1, 1, NAN), vec3(0, 1, 0)}};             // NaN
  for (const auto& corners : bad) {
    EXPECT_THROW(gi::make_polygon(corners), std::invalid_argument);
    gi::Polygon p = square;
    p.corners = corners;  // hand-built: the scene checks it
    EXPECT_THROW(gi::FormFactorScene({square, p}), std::invalid_argument);
  }
}
