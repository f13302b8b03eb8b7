// A twisted quadrilateral (non-planar within make_polygon's 1%) in a closed room:
// no element of a patch may hide the patch's hemicube or rays, rows must sum to 1,
// and the furnace answer B = E / (1 - rho) must hold. The room is the unit cube with
// the corners of its wall x = 1 moved along x by +-0.006 (a saddle, lifted 0.008 at
// its corners; the Cornell box's red wall is like it), which keeps the walls that
// meet it flat, so the room stays closed.
#include <gtest/gtest.h>

#include <numbers>
#include <numeric>

#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/radiosity_system.hpp"
#include "gi/radiosity/system/solvers.hpp"

using gi::vec3;

namespace {

std::vector<gi::Surface> twisted_room(double t) {
  const vec3 p000(0, 0, 0), p100(1 + t, 0, 0), p010(0, 1, 0), p110(1 - t, 1, 0), p001(0, 0, 1), p101(1 - t, 0, 1),
      p011(0, 1, 1), p111(1 + t, 1, 1);
  const gi::Color grey(0.5);
  return {{"floor", {p000, p001, p101, p100}, grey},      {"ceiling", {p010, p110, p111, p011}, grey},
          {"wall x=0", {p000, p010, p011, p001}, grey},   {"twisted wall", {p100, p101, p111, p110}, grey},
          {"wall z=0", {p000, p100, p110, p010}, grey},   {"wall z=1", {p001, p011, p111, p101}, grey}};
}

double sum(const std::vector<double>& row) { return std::accumulate(row.begin(), row.end(), 0.0); }

gi::FormFactorSettings with(gi::FormFactorMethod method) {
  gi::FormFactorSettings s;
  s.method = method;
  s.rays = 4000;
  s.tolerance = 1e-8;
  return s;
}

}  // namespace

TEST(TwistedQuad, TheRoomIsTwistedAndClosed) {
  const gi::Polygon wall = gi::make_polygon(twisted_room(0.006)[3].corners);
  EXPECT_NEAR(gi::lift(wall), 0.008, 1e-4) << "the test must exercise a twist";
  for (const gi::Surface& s : twisted_room(0.006))
    if (s.name != "twisted wall") {
      EXPECT_EQ(gi::lift(gi::make_polygon(s.corners)), 0.0) << s.name;
    }
}

TEST(TwistedQuad, HemicubeRowsOfEveryElementAndPatchSumToOne) {
  // Elements 2 x 2 per patch, so a patch's own elements surround its hemicube.
  const gi::Mesh mesh = gi::make_mesh(twisted_room(0.006), {0.5, 2});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const gi::FormFactorSettings hemicube = with(gi::FormFactorMethod::Hemicube);
  for (int i = 0; i < static_cast<int>(mesh.elements.size()); ++i) {
    const std::vector<double> row = gi::form_factor_row(scene, scene.polygons()[i], i, hemicube);
    ASSERT_NEAR(sum(row), 1.0, 1e-12) << "element " << i << " of " << mesh.surfaces[mesh.elements[i].surface].name;
    ASSERT_EQ(row[i], 0.0);
  }
  for (const gi::Patch& patch : mesh.patches) {
    const std::vector<double> row = gi::form_factor_row(scene, patch.shape, 0, hemicube);
    ASSERT_NEAR(sum(row), 1.0, 1e-12) << mesh.surfaces[patch.surface].name;
    for (int e = patch.first_element; e < patch.first_element + patch.element_count; ++e)
      ASSERT_EQ(row[e], 0.0) << "a patch's own element " << e << " in its hemicube";
  }
}

TEST(TwistedQuad, NoMethodLetsAPatchSeeOrHideBehindItsOwnElements) {
  const gi::Mesh mesh = gi::make_mesh(twisted_room(0.006), {0.5, 2});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  for (gi::FormFactorMethod method : {gi::FormFactorMethod::Differential, gi::FormFactorMethod::Analytic,
                                      gi::FormFactorMethod::MonteCarlo, gi::FormFactorMethod::Hemicube})
    for (int p = 0; p < static_cast<int>(mesh.patches.size()); ++p) {
      const gi::Patch& patch = mesh.patches[p];
      if (mesh.surfaces[patch.surface].name != "twisted wall") continue;
      const std::vector<double> row = gi::form_factor_row(scene, patch.shape, p, with(method));
      for (int e = patch.first_element; e < patch.first_element + patch.element_count; ++e)
        EXPECT_EQ(row[e], 0.0) << gi::name(method) << ": patch " << p << " to its element " << e;
      // Rays and the analytic method take the patch as its outline lifted to its highest
      // corner; near the room's edges that plane reaches past the walls by up to the
      // twist (0.008 here), and a few rays leave: at most 1e-4 of a row for this room.
      if (method == gi::FormFactorMethod::MonteCarlo) {
        EXPECT_GE(sum(row), 1 - 1e-3) << p;
      } else if (method == gi::FormFactorMethod::Analytic) {
        EXPECT_NEAR(sum(row), 1.0, 1e-4) << p;
      }
    }
}

TEST(TwistedQuad, DifferentialSeesATwistedReceiverAndATwistedSender) {
  // Once the centre of a twisted quad lay behind its own triangles, and the shadow ray
  // between the centres hit them: F = 0 instead of about 0.32.
  const gi::Polygon flat = gi::make_polygon({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
  const gi::Polygon twisted = gi::make_polygon({vec3(0, 0, 1), vec3(0, 1, 1.008), vec3(1, 1, 1), vec3(1, 0, 1.008)});
  const gi::Polygon level = gi::make_polygon({vec3(0, 0, 1), vec3(0, 1, 1), vec3(1, 1, 1), vec3(1, 0, 1)});
  const gi::FormFactorSettings differential = with(gi::FormFactorMethod::Differential);
  const double expected = gi::form_factor_row(gi::FormFactorScene({flat, level}), flat, 0, differential)[1];
  EXPECT_NEAR(expected, 1 / std::numbers::pi, 0.01) << "cos cos A / (pi r^2) for unit squares 1 apart";
  EXPECT_NEAR(gi::form_factor_row(gi::FormFactorScene({flat, twisted}), flat, 0, differential)[1], expected,
              0.02 * expected);
  EXPECT_NEAR(gi::form_factor_row(gi::FormFactorScene({twisted, flat}), twisted, 0, differential)[1], expected,
              0.02 * expected);
}

TEST(TwistedQuad, TheFurnaceAnswerHolds) {
  // Uniform rho and E in a closed room: B = E / (1 - rho) everywhere, exactly when every
  // row sums to 1. Hemicube elements, solved directly.
  const gi::Mesh mesh = gi::make_mesh(twisted_room(0.006), {0.5, 2});
  gi::FormFactorMatrix F = gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), 100, 2);
  gi::RadiositySystem system = gi::make_system(mesh, std::move(F));
  system.emission.assign(system.size(), gi::Color(1.0));
  const gi::SolverResult r = gi::solve_direct(system);
  for (const gi::Color& b : r.B) ASSERT_NEAR(b.x, 2.0, 1e-11);
}
