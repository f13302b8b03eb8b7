#include "gi/radiosity/mesh/radiosity_scene_file.hpp"

#include <algorithm>
#include <stdexcept>

#include "gi/core/did_you_mean.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"

namespace gi {

namespace {

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

// The names of the surfaces that emit, each once.
std::vector<std::string> light_names(const RadiosityScene& scene) {
  std::vector<std::string> names;
  for (const Surface& s : scene.surfaces)
    if (max_component(s.emission) > 0 && std::find(names.begin(), names.end(), s.name) == names.end())
      names.push_back(s.name);
  return names;
}

}  // namespace

RadiosityScene radiosity_scene(const SceneFile& file, std::vector<std::string>& warnings) {
  const char* const flat_only = "radiosity meshes flat polygons only (quads, polygons and meshes); this scene is for "
                                "the ray-tracing lessons 01-04";
  if (file.first_sphere) throw SceneError(*file.first_sphere, flat_only);
  if (file.first_plane) throw SceneError(*file.first_plane, flat_only);
  RadiosityScene scene;
  scene.name = file.scene.name;
  scene.camera = file.scene.camera;
  std::vector<bool> warned(file.scene.materials.size(), false);
  for (const FilePolygon& p : file.polygons) {
    const Material& m = file.scene.materials[p.material];
    // rho = k_d; a Lambertian emitter of radiance L has the exitance E = pi L.
    std::array<std::array<vec3, 4>, 3> pieces;
    for (int i = 0; i < flat_pieces(p.shape, pieces); ++i)
      scene.surfaces.push_back({p.name, pieces[i], m.diffuse, pi * m.emission});
    if (max_component(m.diffuse) > 1 && !warned[p.material]) {
      warned[p.material] = true;
      warnings.push_back(file.file + ": material '" + m.name + "' reflects more than it receives (diffuse above 1): " +
                         "radiosity makes light from nowhere");
    }
  }
  if (light_names(scene).empty())
    throw SceneError(FileLocation{file.file, 1, 1, ""},
                     "no quad, polygon or mesh face emits light, and radiosity is lit by those alone (point and quad "
                     "lights are the ray tracer's): give one a material with an \"emission\"");
  warnings.insert(warnings.end(), file.warnings.begin(), file.warnings.end());
  return scene;
}

void check_meshable(const RadiosityScene& scene, const std::string& file, int most_surfaces) {
  if (scene.surfaces.size() > static_cast<std::size_t>(most_surfaces))
    throw SceneError(file, std::to_string(scene.surfaces.size()) + " surfaces (a triangle makes three), more than the " +
                               std::to_string(most_surfaces) + " patches this lesson solves for in seconds");
  try {
    (void)make_mesh(scene.surfaces, {});  // one patch per surface: the surfaces' own checks
  } catch (const std::invalid_argument& e) {
    throw SceneError(file, e.what());
  }
}

RadiosityScene load_radiosity_scene(const std::string& choice, const SceneChanges& changes, int most_surfaces,
                                    std::vector<std::string>& warnings, const SceneFileRules& rules) {
  RadiosityScene scene;
  const std::vector<std::string> names = radiosity_scene_names(), ray_traced = scene_names();
  if (names_a_file(choice)) {
    SceneFileRules limited = rules;  // every polygon is one surface at least
    limited.max_polygons = std::min(limited.max_polygons, static_cast<std::size_t>(std::max(most_surfaces, 0)));
    scene = radiosity_scene(read_scene_file(choice, limited), warnings);
    check_meshable(scene, choice, most_surfaces);
  } else if (std::find(names.begin(), names.end(), choice) != names.end()) {
    scene = make_radiosity_scene(choice);
  } else {
    const bool for_the_ray_tracer = std::find(ray_traced.begin(), ray_traced.end(), choice) != ray_traced.end();
    throw std::invalid_argument((for_the_ray_tracer ? "'" + choice + "' is a scene for the ray tracer, not radiosity"
                                                    : "unknown scene '" + choice.substr(0, 64) + "'" +
                                                          did_you_mean(choice, names)) +
                                "; radiosity scenes: " + listed(names) + "; or a scene file ending in .json");
  }
  if (changes.camera) scene.camera = changed_camera(scene.camera, *changes.camera);
  scale_lights(scene, changes.light_scales);
  return scene;
}

void scale_lights(RadiosityScene& scene, const std::vector<LightScale>& scales) {
  const std::vector<std::string> lights = light_names(scene);
  for (const LightScale& scale : scales) {
    if (std::find(lights.begin(), lights.end(), scale.light) == lights.end())
      throw std::invalid_argument("light scale: no light is named '" + scale.light.substr(0, 64) + "'" +
                                  did_you_mean(scale.light, lights) + "; the lights of " + scene.name + ": " +
                                  listed(lights));
    if (!(scale.factor >= 0 && scale.factor <= 1e6))
      throw std::invalid_argument("light scale: the factor must lie in [0, 1e6]");
    for (Surface& s : scene.surfaces)
      if (s.name == scale.light) s.emission *= scale.factor;
  }
  if (!scales.empty() && light_names(scene).empty())
    throw std::invalid_argument("light scale: every light is off, so there would be nothing to see");
}

}  // namespace gi
