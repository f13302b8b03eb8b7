// Every built-in scene is also a file under lessons/scenes/. The file must
// hold the same scene, value for value, and render the same bytes: the C++ is the
// source, so when it changes (new reflectances, say) these tests name the value the
// file must follow.
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/mesh/radiosity_scene_file.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/scene_file.hpp"

namespace {

std::string scene_file(const std::string& name) { return std::string(GI_SOURCE_DIR) + "/lessons/scenes/" + name + ".json"; }

std::string text(const gi::vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return s.str();
}

// The first value in which the file's scene differs from the code's, or "".
class Differences {
 public:
  template <class T>
  void same(const std::string& what, const T& file, const T& code) {
    if (found.empty() && !(file == code)) found = what + ": the file has " + show(file) + ", the code " + show(code);
  }
  std::string found;

 private:
  static std::string show(const gi::vec3& v) { return text(v); }
  static std::string show(const std::string& s) { return "'" + s + "'"; }
  template <class T>
  static std::string show(const T& x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  }
};

std::string difference(const gi::Scene& f, const gi::Scene& c) {
  Differences d;
  d.same("name", f.name, c.name);
  d.same("camera.eye", f.camera.eye, c.camera.eye);
  d.same("camera.look_at", f.camera.look_at, c.camera.look_at);
  d.same("camera.up", f.camera.up, c.camera.up);
  d.same("camera.fov", f.camera.vertical_fov, c.camera.vertical_fov);
  d.same("background", f.background, c.background);
  d.same("ambient_light", f.ambient_light, c.ambient_light);
  d.same("materials: count", f.materials.size(), c.materials.size());
  for (std::size_t i = 0; i < std::min(f.materials.size(), c.materials.size()); ++i) {
    const gi::Material &a = f.materials[i], &b = c.materials[i];
    const std::string m = "materials[" + std::to_string(i) + "].";
    d.same(m + "name", a.name, b.name), d.same(m + "diffuse", a.diffuse, b.diffuse);
    d.same(m + "ambient", a.ambient, b.ambient), d.same(m + "specular", a.specular, b.specular);
    d.same(m + "shininess", a.shininess, b.shininess), d.same(m + "mirror", a.mirror, b.mirror);
    d.same(m + "transmission", a.transmission, b.transmission), d.same(m + "ior", a.ior, b.ior);
    d.same(m + "emission", a.emission, b.emission), d.same(m + "checker_size", a.checker_size, b.checker_size);
    d.same(m + "checker_diffuse", a.checker_diffuse, b.checker_diffuse);
  }
  d.same("spheres: count", f.spheres.size(), c.spheres.size());
  for (std::size_t i = 0; i < std::min(f.spheres.size(), c.spheres.size()); ++i) {
    const std::string s = "spheres[" + std::to_string(i) + "].";
    d.same(s + "center", f.spheres[i].center, c.spheres[i].center);
    d.same(s + "radius", f.spheres[i].radius, c.spheres[i].radius);
    d.same(s + "material", f.spheres[i].material, c.spheres[i].material);
  }
  d.same("planes: count", f.planes.size(), c.planes.size());
  for (std::size_t i = 0; i < std::min(f.planes.size(), c.planes.size()); ++i) {
    const std::string p = "planes[" + std::to_string(i) + "].";
    d.same(p + "point", f.planes[i].point, c.planes[i].point);
    d.same(p + "normal", f.planes[i].normal, c.planes[i].normal);
    d.same(p + "material", f.planes[i].material, c.planes[i].material);
  }
  d.same("quads: count", f.quads.size(), c.quads.size());
  for (std::size_t i = 0; i < std::min(f.quads.size(), c.quads.size()); ++i) {
    const std::string q = "quads[" + std::to_string(i) + "] (boxes' faces first).";
    d.same(q + "corner", f.quads[i].corner, c.quads[i].corner);
    d.same(q + "edge_u", f.quads[i].edge_u, c.quads[i].edge_u);
    d.same(q + "edge_v", f.quads[i].edge_v, c.quads[i].edge_v);
    d.same(q + "material", f.quads[i].material, c.quads[i].material);
  }
  d.same("triangles: count", f.triangles.size(), c.triangles.size());
  d.same("point_lights: count", f.lights.size(), c.lights.size());
  for (std::size_t i = 0; i < std::min(f.lights.size(), c.lights.size()); ++i) {
    d.same("point_lights[" + std::to_string(i) + "].position", f.lights[i].position, c.lights[i].position);
    d.same("point_lights[" + std::to_string(i) + "].intensity", f.lights[i].intensity, c.lights[i].intensity);
  }
  d.same("quad_lights: count", f.area_lights.size(), c.area_lights.size());
  for (std::size_t i = 0; i < std::min(f.area_lights.size(), c.area_lights.size()); ++i) {
    const gi::QuadLight &a = f.area_lights[i], &b = c.area_lights[i];
    const std::string l = "quad_lights[" + std::to_string(i) + "].";
    d.same(l + "corner", a.shape.corner, b.shape.corner), d.same(l + "edge_u", a.shape.edge_u, b.shape.edge_u);
    d.same(l + "edge_v", a.shape.edge_v, b.shape.edge_v), d.same(l + "intensity", a.intensity, b.intensity);
  }
  return d.found;
}

std::string difference(const gi::RadiosityScene& f, const gi::RadiosityScene& c) {
  Differences d;
  d.same("name", f.name, c.name);
  d.same("camera.eye", f.camera.eye, c.camera.eye);
  d.same("camera.look_at", f.camera.look_at, c.camera.look_at);
  d.same("camera.up", f.camera.up, c.camera.up);
  d.same("camera.fov", f.camera.vertical_fov, c.camera.vertical_fov);
  d.same("surfaces: count", f.surfaces.size(), c.surfaces.size());
  for (std::size_t i = 0; i < std::min(f.surfaces.size(), c.surfaces.size()); ++i) {
    const gi::Surface &a = f.surfaces[i], &b = c.surfaces[i];
    const std::string s = "polygons[" + std::to_string(i) + "] ('" + b.name + "').";
    d.same(s + "name", a.name, b.name);
    for (int k = 0; k < 4; ++k) d.same(s + "corners[" + std::to_string(k) + "]", a.corners[k], b.corners[k]);
    d.same(s + "material's diffuse (rho)", a.reflectance, b.reflectance);
    d.same(s + "material's emission times pi (E)", a.emission, b.emission);
  }
  return d.found;
}

bool same_bytes(const gi::Image& a, const gi::Image& b) {
  return a.same_size(b) && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(gi::Pixel)) == 0;
}

// A picture of the radiosity solution: 40 elements or so, hemicube form factors,
// the direct solution, smooth shading.
gi::Image radiosity_picture(const gi::RadiosityScene& scene) {
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 40, 1), 1});
  const gi::FormFactorScene receivers(gi::element_shapes(mesh));
  gi::FormFactorSettings hemicube;
  hemicube.hemicube_resolution = 20;
  const gi::RadiositySystem system = gi::make_system(mesh, gi::form_factor_matrix(receivers, hemicube, 2));
  gi::DisplaySettings display;
  display.width = 48, display.height = 40;
  return gi::render_radiosity_picture(receivers, mesh, gi::solve_direct(system).B, scene.camera, display, 1, 0).radiance;
}

}  // namespace

TEST(SceneFiles, EveryBuiltInRayTracingSceneIsAFileOfTheSameValues) {
  for (const std::string& name : gi::scene_names()) {
    std::vector<std::string> warnings;
    const gi::Scene from_file = gi::load_scene(scene_file(name), warnings);
    EXPECT_TRUE(warnings.empty()) << name << ": " << warnings.front();
    EXPECT_EQ(difference(from_file, gi::make_scene(name)), "")
        << "lessons/scenes/" << name << ".json differs from the built-in scene (builtin_scenes.cpp); the file follows "
        << "the code";
  }
}

TEST(SceneFiles, EveryBuiltInRayTracingSceneRendersTheSameBytesFromItsFile) {
  gi::RenderSettings settings;
  settings.width = 64, settings.height = 48;
  settings.trace.max_depth = 4;
  settings.sampling = {gi::Sampler::Jittered, 2};
  settings.trace.soft_shadows = {gi::LightSampling::Jittered, 2};
  for (const std::string& name : gi::scene_names()) {
    std::vector<std::string> warnings;
    const gi::Image code = gi::render(gi::make_world(gi::make_scene(name)), settings, 1, 2).image;
    const gi::Image file = gi::render(gi::make_world(gi::load_scene(scene_file(name), warnings)), settings, 1, 2).image;
    EXPECT_TRUE(same_bytes(code, file)) << name << ": the file's picture differs from the built-in scene's";
    EXPECT_EQ(gi::fingerprint(gi::make_scene(name)), gi::fingerprint(gi::load_scene(scene_file(name), warnings)));
  }
}

TEST(SceneFiles, EveryBuiltInRadiositySceneIsAFileOfTheSameSurfacesAndPicture) {
  for (const std::string& name : gi::radiosity_scene_names()) {
    std::vector<std::string> warnings;
    const gi::RadiosityScene from_file = gi::radiosity_scene(gi::read_scene_file(scene_file(name)), warnings);
    const gi::RadiosityScene code = gi::make_radiosity_scene(name);
    EXPECT_TRUE(warnings.empty()) << name << ": " << warnings.front();
    EXPECT_EQ(difference(from_file, code), "")
        << "lessons/scenes/" << name << ".json differs from the built-in radiosity scene (radiosity_scenes.hpp); "
        << "the file follows the code";
    EXPECT_TRUE(same_bytes(radiosity_picture(code), radiosity_picture(from_file)))
        << name << ": the file's radiosity picture differs from the built-in scene's";
  }
}
