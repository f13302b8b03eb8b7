#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/scene_changes.hpp"
#include "gi/scene/scene_file.hpp"

namespace gi {

// Radiosity's view of a scene file (scene_file.hpp): every quad, polygon and mesh
// face becomes a surface -- a triangle as the three quadrilaterals of flat_pieces --
// named as the file names it, with rho = its material's diffuse colour and E = pi
// times its emission (exitance from radiance, for a Lambertian emitter). Point and
// quad lights are the ray tracer's and are left out. Throws SceneError at the first
// sphere or plane (radiosity meshes flat polygons only) and when no surface emits.
// Warns of a reflectance above 1 (light from nowhere).
RadiosityScene radiosity_scene(const SceneFile& file, std::vector<std::string>& warnings);

// Throws SceneError naming `file` if the scene has more than `most_surfaces` surfaces
// (every surface is one patch at least, and a lesson's solver has a largest size it runs
// in seconds) or cannot be meshed: make_mesh's checks, such as two surfaces that
// overlap in one plane. The count comes first: those checks compare every pair.
void check_meshable(const RadiosityScene& scene, const std::string& file, int most_surfaces);

// --scene NAME|FILE for the radiosity lessons: a built-in radiosity scene
// (radiosity_scenes.hpp) or a scene file (checked by check_meshable), with the
// command line's changes applied. Throws std::invalid_argument for an unknown name (or
// a ray-tracing scene's), a degenerate camera or a light scale that names no light;
// SceneError for a bad file.
// A file is read under `rules` (scene_file.hpp), its polygons also limited to
// `most_surfaces` as they are read: reading stops there, before any mesh is made.
RadiosityScene load_radiosity_scene(const std::string& choice, const SceneChanges& changes, int most_surfaces,
                                    std::vector<std::string>& warnings, const SceneFileRules& rules = {});

// Multiplies the emission of each surface a scale names. Throws std::invalid_argument,
// listing the scene's lights, for a name no emitting surface has, and when the scales
// leave no light on.
void scale_lights(RadiosityScene& scene, const std::vector<LightScale>& scales);

}  // namespace gi
