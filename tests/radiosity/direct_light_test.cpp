// Exact direct light (direct_light.hpp): the closed form where nothing blocks, zero
// where everything does, Monte Carlo form factors (an independent method) in a
// penumbra, and the split B = E + B' that solves the same system as before.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/display/direct_display.hpp"
#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"

using gi::Color;

namespace {

gi::Mesh mesh_of(const gi::RadiosityScene& scene, int elements_per_side) {
  return gi::make_mesh(scene.surfaces, {1e30, elements_per_side});
}

std::vector<Color> direct(const gi::Mesh& mesh, int cells, int points, int threads = 0) {
  return gi::direct_radiosity(gi::FormFactorScene(gi::element_shapes(mesh)), mesh, {cells, points}, threads);
}

// Two unit squares a unit apart, the bottom one the light (E = 1), the top grey (0.5):
// D = rho E F with F the parallel squares' closed form, 0.19982. Summed over a 4 x 4
// mesh of the top, area-weighted, it is the same.
TEST(DirectLight, UnoccludedIsTheClosedForm) {
  const double F = gi::ff_parallel_rectangles(1, 1, 1);
  const gi::Mesh one = mesh_of(gi::parallel_squares(), 1);
  const std::vector<Color> D = direct(one, 4, 8);
  EXPECT_NEAR(D[1].x, 0.5 * F, 1e-6 * F);  // 8 x 8 Gauss points: 2e-7 relative
  EXPECT_EQ(D[0], Color(0.0));  // the light's own reflectance is 0
  const gi::Mesh fine = mesh_of(gi::parallel_squares(), 4);
  const std::vector<Color> Df = direct(fine, 4, 4);
  double power = 0;
  for (std::size_t i = 0; i < fine.elements.size(); ++i) power += fine.elements[i].shape.area * Df[i].y;
  EXPECT_NEAR(power, 0.5 * F, 1e-6 * F);
}

// A slab wider than both squares between them: nothing reaches the top, and the
// slab's underside gets the closed form for its own distance.
TEST(DirectLight, HiddenLightGivesNothing) {
  gi::RadiosityScene scene = gi::parallel_squares(1.0, 1.0);
  const double lo = 0.49, hi = 0.51;
  const Color grey(0.5);
  scene.surfaces.push_back({"slab underside", {{{-1, lo, -1}, {1, lo, -1}, {1, lo, 1}, {-1, lo, 1}}}, grey});
  scene.surfaces.push_back({"slab top", {{{-1, hi, -1}, {-1, hi, 1}, {1, hi, 1}, {1, hi, -1}}}, grey});
  const gi::Mesh mesh = mesh_of(scene, 1);
  const std::vector<Color> D = direct(mesh, 8, 4);
  EXPECT_EQ(D[1], Color(0.0)) << "the top is behind the slab";
  EXPECT_EQ(D[3], Color(0.0)) << "the slab's top faces away";
  // The underside, 2 x 2 over the 1 x 1 light and 0.49 above it, sees all of it:
  // D = rho E F with F the offset parallel rectangles' closed form. (8 x 8 points over
  // an integrand that peaks in the middle: 3e-4 relative.)
  const double expected = 0.5 * gi::ff_parallel_rectangles_offset(-1, 1, -1, 1, -0.5, 0.5, -0.5, 0.5, lo);
  const std::vector<Color> D8 = direct(mesh, 8, 8);
  EXPECT_NEAR(D8[2].x, expected, 1e-3 * expected);
}

// In the penumbra of occluded_squares (a half-size blocker halfway), the light each
// element of the top gets, D_i / (rho_i E), is its form factor to the light with
// occlusion: Monte Carlo's row (200 000 rays, its own standard error) is an
// independent estimate. Allowed: 4.5 standard errors (a false failure about once in
// 10^4 runs over the 16 elements) plus 0.2% of F for the 16 x 16 light cells.
TEST(DirectLight, PenumbraAgreesWithMonteCarlo) {
  const gi::Mesh mesh = mesh_of(gi::occluded_squares(), 4);
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const std::vector<Color> D = gi::direct_radiosity(scene, mesh, {16, 4}, 0);
  gi::FormFactorSettings mc;
  mc.method = gi::FormFactorMethod::MonteCarlo;
  mc.rays = 200000;
  // The light, "bottom", is cut into 4 x 4 elements too: F to it is the sum over them.
  std::vector<int> light;
  for (std::size_t j = 0; j < mesh.elements.size(); ++j)
    if (mesh.surfaces[mesh.elements[j].surface].name == "bottom") light.push_back(static_cast<int>(j));
  ASSERT_EQ(light.size(), 16u);
  const gi::Polygon whole_light = gi::make_polygon(mesh.surfaces[mesh.elements[light[0]].surface].corners);
  int shadowed = 0;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    if (mesh.surfaces[mesh.elements[i].surface].name != "top") continue;
    const gi::FormFactorRow row =
        gi::form_factor_row_with_diagnostics(scene, mesh.elements[i].shape, static_cast<int>(i), mc);
    double estimate = 0, variance = 0;
    for (int j : light) estimate += row.F[j], variance += row.error[j] * row.error[j];
    const double exact = D[i].x / 0.5, se = std::sqrt(variance);
    EXPECT_NEAR(exact, estimate, 4.5 * se + 2e-3 * estimate) << "element " << i;
    shadowed += exact < 0.99 * gi::form_factor_analytic(mesh.elements[i].shape, whole_light, 8);
  }
  EXPECT_GE(shadowed, 4) << "the blocker must shade some of the top";
}

// With D = R F E from the same F, B = E + B' where (I - R F) B' = D is exactly the
// solution of (I - R F) B = E: the split changes where the first bounce comes from,
// not the equation.
TEST(DirectLight, SplitSolvesTheSameSystem) {
  const gi::RadiosityScene box = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {gi::patch_size_for(box.surfaces, 120, 1), 1});
  const gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), {}, 0));
  std::vector<Color> D(system.size(), Color(0.0));
  for (int i = 0; i < system.size(); ++i)
    for (int j = 0; j < system.size(); ++j) D[i] += system.rho[i] * system.F(i, j) * system.emission[j];
  const std::vector<Color> whole = gi::solve_direct(system).B;
  const std::vector<Color> split = gi::with_emission(system, gi::solve_direct(gi::indirect_system(system, D)).B);
  for (int i = 0; i < system.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(split[i][c], whole[i][c], 1e-10 * (1 + whole[i][c])) << i;
}

TEST(DirectLight, SameForAnyThreadCount) {
  const gi::RadiosityScene box = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {gi::patch_size_for(box.surfaces, 200, 1), 1});
  EXPECT_EQ(direct(mesh, 4, 2, 1), direct(mesh, 4, 2, 3));
}

TEST(DirectLight, RejectsBadSettings) {
  const gi::Mesh mesh = mesh_of(gi::parallel_squares(), 1);
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  EXPECT_THROW(gi::direct_radiosity(scene, mesh, {0, 2}, 0), std::invalid_argument);
  EXPECT_THROW(gi::direct_radiosity(scene, mesh, {8, 9}, 0), std::invalid_argument);
  const gi::Mesh other = mesh_of(gi::parallel_squares(), 2);
  EXPECT_THROW(gi::direct_radiosity(scene, other, {}, 0), std::invalid_argument);
  EXPECT_THROW(gi::indirect_system(gi::make_system(mesh, {}), {}), std::invalid_argument);
}

}  // namespace

namespace {

// The direct light drawn per pixel (direct_display.hpp): looking up at the top of the
// parallel squares from between them, each pixel shows rho E F(x -> light) / pi at the
// point it sees, F by the contour integral (nothing blocks). A pixel's eye ray lands
// anywhere in it: 1e-3 relative covers F's change across one of 63 x 63 pixels.
TEST(DirectDisplay, EachPixelShowsItsPointsDirectLight) {
  const gi::RadiosityScene scene = gi::parallel_squares();
  const gi::Mesh mesh = mesh_of(scene, 2);
  const gi::FormFactorScene elements(gi::element_shapes(mesh));
  gi::DisplaySettings display;
  display.width = display.height = 63;
  display.samples = 1;
  const gi::Camera camera{{0, 0.5, 0}, {0, 1, 0}, {0, 0, 1}, 30};
  const gi::DirectLighting lights(mesh, 8);
  const gi::Image picture =
      gi::render_display(gi::DirectRadiance{elements, mesh, lights}, camera, display, 1, 0).radiance;
  const gi::CameraFrame frame = gi::camera_frame(camera, 63, 63);
  const gi::Polygon light = gi::make_polygon(scene.surfaces[0].corners);
  for (int y = 0; y < 63; y += 31)
    for (int x = 0; x < 63; x += 31) {
      const gi::Ray ray = gi::primary_ray(frame, x + 0.5, y + 0.5);
      const gi::vec3 point = ray.at((1.0 - 0.5) / ray.direction.y);
      const double expected = 0.5 * gi::form_factor_point_to_polygon(point, {0, -1, 0}, light) / gi::pi;
      EXPECT_NEAR(picture.at(x, y).x, expected, 1e-3 * expected) << x << ", " << y;
    }
  // What bounced more than once: B - E - D, zero where B is only E + D.
  const std::vector<Color> D = direct(mesh, 8, 2), B = [&] {
    std::vector<Color> b = D;
    for (std::size_t i = 0; i < b.size(); ++i) b[i] += mesh.emission(mesh.elements[i]);
    return b;
  }();
  for (const Color& c : gi::indirect_part(mesh, B, D)) EXPECT_EQ(c, Color(0.0));
  EXPECT_THROW(gi::indirect_part(mesh, B, {}), std::invalid_argument);
}

}  // namespace
