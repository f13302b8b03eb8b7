// Ray offsets are relative to the scene's scale (scene_scale.hpp), so a scene scaled
// by any factor draws the same picture. Scaled by a power of two every number in the
// renderer is scaled exactly, so the pictures are the same bytes; scaled by 10^k the
// scene's coordinates are rounded once more, and the pictures agree within round-off:
// a relative RMS difference of at most 1e-5 (1.4e-6 measured, Whitted's scene at 1e-5;
// 7e-7 for the hemicube's radiosity) and no pixel off by 1% of the picture's mean.
// Every lesson that casts rays from a surface: Whitted's tracer (02), with jittered
// eye rays (03) and soft shadows (04); radiosity's form factors and display (08, 11);
// the path tracer (14); the two-pass renderer (16). With the fixed offset of 1e-6
// scene units they had, 02's picture differed by 7% at 1e-5 (shadows missing).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_trace.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/render/film.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/soft_shadow_scene.hpp"
#include "gi/twopass/radiosity_pass.hpp"
#include "gi/twopass/two_pass.hpp"
#include "gi/twopass/two_pass_scene.hpp"

namespace {

using gi::vec3;

// Powers of two, to 2^-17 (7.6e-6) and 2^17 (1.3e5): exact; and the powers of ten.
const std::vector<double> exact_scales = {std::ldexp(1.0, -17), std::ldexp(1.0, -7), std::ldexp(1.0, 10),
                                          std::ldexp(1.0, 17)};
const std::vector<double> decimal_scales = {1e-5, 1e-3, 1e3, 1e5};

gi::Quad scaled(gi::Quad q, double k) {
  q.corner *= k, q.edge_u *= k, q.edge_v *= k;
  return q;
}
gi::Camera scaled(gi::Camera c, double k) {
  c.eye *= k, c.look_at *= k;
  return c;
}

// Every point and length times k; directions, colours and angles kept. Whitted's
// lights do not fall off with distance and the path tracer's emit radiance, so the
// same light lights the scaled scene alike.
gi::Scene scaled(gi::Scene s, double k) {
  for (gi::Material& m : s.materials) m.checker_size *= k;
  for (gi::Sphere& x : s.spheres) x.center *= k, x.radius *= k;
  for (gi::Plane& x : s.planes) x.point *= k;
  for (gi::Quad& x : s.quads) x = scaled(x, k);
  for (gi::Triangle& x : s.triangles) x.a *= k, x.b *= k, x.c *= k;
  for (gi::PointLight& x : s.lights) x.position *= k;
  for (gi::QuadLight& x : s.area_lights) x.shape = scaled(x.shape, k);
  s.camera = scaled(s.camera, k);
  return s;
}

// Radiosity's exitance E is per area: the scaled surfaces keep it.
std::vector<gi::Surface> scaled(std::vector<gi::Surface> surfaces, double k) {
  for (gi::Surface& s : surfaces)
    for (vec3& c : s.corners) c *= k;
  return surfaces;
}

// sqrt(sum (a - b)^2 / sum b^2) over pixels and channels, and the share of pixels
// that differ by more than 1% of the picture's mean.
struct Difference {
  double relative_rms, share_off;
};
Difference difference(const gi::Image& a, const gi::Image& b) {
  double d2 = 0, b2 = 0, mean = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) mean += b.pixels[i][c] / (3.0 * b.pixels.size());
  std::size_t off = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - b.pixels[i][c];
      d2 += d * d, b2 += double(b.pixels[i][c]) * b.pixels[i][c];
      differs = differs || std::abs(d) > 0.01 * mean;
    }
    off += differs;
  }
  return {std::sqrt(d2 / b2), double(off) / a.pixels.size()};
}

bool same_bytes(const gi::Image& a, const gi::Image& b) {
  if (!a.same_size(b)) return false;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    if (a.pixels[i] != b.pixels[i]) return false;
  return true;
}

// `draw(k)` is the picture of the scene scaled by k. The same bytes at the exact
// scales; within `rms` and `share` (of pixels off by 1% of the mean) at the decimal.
template <class Draw>
void expect_scale_free(const std::string& what, Draw draw, double rms, double share) {
  const gi::Image unit = draw(1.0);
  for (const double k : exact_scales) EXPECT_TRUE(same_bytes(draw(k), unit)) << what << " scaled by " << k;
  for (const double k : decimal_scales) {
    const Difference d = difference(draw(k), unit);
    EXPECT_LE(d.relative_rms, rms) << what << " scaled by " << k;
    EXPECT_LE(d.share_off, share) << what << " scaled by " << k;
  }
}

gi::Image whitted(const gi::Scene& scene, gi::RenderSettings settings) {
  settings.width = 64, settings.height = 48;
  return gi::render(gi::make_world(scene), settings, 1, 2).image;
}

}  // namespace

// Lesson 02: shadow, reflected and refracted rays, depth 8, on each built-in scene.
TEST(ScaleInvariance, WhittedRayTracing) {
  gi::RenderSettings settings;
  settings.trace.max_depth = 8;
  for (const char* name : {"whitted", "spheres", "s10"})
    expect_scale_free(
        std::string("02 ") + name, [&](double k) { return whitted(scaled(gi::make_scene(name), k), settings); }, 1e-5, 0.0);
}

// Lesson 03: jittered eye rays, 4 x 4, on the aliasing scene.
TEST(ScaleInvariance, Antialiasing) {
  gi::RenderSettings settings;
  settings.trace.max_depth = 3;
  settings.sampling = {gi::Sampler::Jittered, 4};
  expect_scale_free(
      "03 aliasing", [&](double k) { return whitted(scaled(gi::make_scene("aliasing"), k), settings); }, 1e-5, 0.0);
}

// Lesson 04: 4 x 4 jittered shadow rays per hit to the area light.
TEST(ScaleInvariance, SoftShadows) {
  gi::RenderSettings settings;
  settings.trace.max_depth = 1;
  settings.trace.soft_shadows = {gi::LightSampling::Jittered, 4};
  expect_scale_free(
      "04 soft", [&](double k) { return whitted(scaled(gi::soft_shadow_scene(1.0), k), settings); }, 1e-5, 0.0);
}

// Lessons 08 and 11: a mesh, hemicube form factors, the solution, its picture.
TEST(ScaleInvariance, Radiosity) {
  const auto draw = [](double k) {
    const gi::RadiosityScene box = gi::cornell_box();
    const std::vector<gi::Surface> surfaces = scaled(box.surfaces, k);
    const gi::Mesh mesh = gi::make_mesh(surfaces, {gi::patch_size_for(surfaces, 150, 1), 1});
    const gi::RadiositySystem system =
        gi::make_system(mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(mesh), 50, 2));
    const gi::FormFactorScene receivers(gi::element_shapes(mesh));
    gi::DisplaySettings display;
    display.width = 48, display.height = 48;
    return gi::render_radiosity_picture(receivers, mesh, gi::solve_direct(system).B, scaled(box.camera, k), display, 1, 2)
        .radiance;
  };
  expect_scale_free("08 cornell", draw, 1e-5, 0.0);
}

// Lesson 14: the path tracer, bounces and next-event rays, 4 paths a pixel.
TEST(ScaleInvariance, PathTracing) {
  const auto draw = [](double k) {
    const gi::PathScene scene = gi::make_path_scene(scaled(gi::make_path_scene_by_name("cornell-spheres"), k));
    gi::Film film = gi::make_film(32, 32, 7);
    gi::path_trace(film, scene, {}, 4, 2);
    return gi::film_mean(film);
  };
  expect_scale_free("14 cornell-spheres", draw, 1e-5, 0.0);
}

// Lesson 16: the radiosity pass (shadow rays for the direct light, hemicube shots)
// and the eye pass (mirror and glass, shadow rays, the final gather).
TEST(ScaleInvariance, TwoPass) {
  const auto draw = [](double k) {
    gi::TwoPassScene scene = gi::make_two_pass_scene("cornell-spheres");
    scene.surfaces = scaled(scene.surfaces, k);
    for (gi::SpecularSphere& s : scene.spheres) s.shape.center *= k, s.shape.radius *= k;
    scene.camera = scaled(scene.camera, k);
    gi::RadiosityPassSettings radiosity;
    radiosity.elements = 150;
    radiosity.form_factors.hemicube_resolution = 50;
    gi::TwoPassSettings eye;
    eye.width = eye.height = 32, eye.samples = 1, eye.gather_strata = 2;
    return gi::render_two_pass(scene, gi::radiosity_pass(scene, radiosity, 2).handoff, eye, 1, 2);
  };
  expect_scale_free("16 cornell-spheres", draw, 1e-5, 0.0);
}
