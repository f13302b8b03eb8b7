#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gi/scene/flat_polygon.hpp"
#include "gi/scene/scene.hpp"
#include "gi/scene/scene_error.hpp"

namespace gi {

// A scene file: a scene written as JSON, read without recompiling (docs/scene_files.md
// has examples; lessons/scenes/ holds every built-in scene as one). The schema, key by
// key (a colour is [r, g, b] or one number for a grey, each >= 0; a point is [x, y, z]
// within +-1e6 scene units; any object may also have an "about": a note, ignored):
//
//   name           string   the scene's name in titles and file names      the file's stem
//   camera         object   required
//     eye          point    where the pinhole is                             required
//     look_at      point    the point seen in the middle of the picture      required
//     up           point    which way is up in the picture                   [0, 1, 0]
//     fov          number   vertical field of view, degrees, in (0, 180)     45
//   background     colour   radiance of rays that hit nothing                0
//   ambient_light  colour   I_a of the Phong model                           0
//   materials      array    of material objects; names unique                []
//     name           string   what the shapes call it                      required
//     diffuse        colour   k_d; radiosity's reflectance rho             0.8
//     ambient        number   k_a, in [0, 1e6]                             0
//     specular       colour   k_s, the Phong highlight                     0
//     shininess      number   Phong exponent n, in [0, 1e6]                1
//     mirror         colour   k_r of a mirror                              0
//     transmission   colour   filter of glass: > 0 makes it refract        0
//     ior            number   index of refraction, in (0, 100]             1
//     emission       colour   radiance L the surface gives off; radiosity's
//                             exitance is E = pi L                         0
//     checker_size   number   side of checkerboard squares (x-z plane); 0 off   0
//     checker_diffuse colour  k_d of the other squares                     0
//   spheres        array    {center: point, radius: number in (0, 1e6], material: name}
//   planes         array    {point, normal: point (not zero; normalised), material}
//   boxes          array    {min, max: points, material, name?}: the six faces of an
//                           axis-aligned box as quads (box_quads), fronts outwards
//   quads          array    {corner, edge_u, edge_v: points, material, name?}: the
//                           parallelogram corner + s edge_u + t edge_v; its front is
//                           edge_u x edge_v
//   polygons       array    {corners: 3 or 4 points, counter-clockwise seen from the
//                           front, flat and convex (flat_polygon.hpp), material, name?}
//   meshes         array    {file: an OBJ file, its path relative to this file
//                           (obj_file.hpp), its name ending in .obj, below this
//                           file's folder (SceneFileRules); material?: name for faces
//                           before any usemtl}
//   point_lights   array    {position: point, intensity: colour, not black}
//   quad_lights    array    {corner, edge_u, edge_v: points, intensity: colour, not black}
//
// The ray tracer renders all of it (polygons and mesh faces as triangles) and is lit by
// the point and quad lights; a quad light is not seen, so add an emitting quad where
// it is. Radiosity reads the quads, polygons and mesh faces (with rho = diffuse and
// E = pi emission) and is lit by the surfaces that emit; spheres and planes are not
// flat polygons, so a file with them is for the ray tracer only.
//
// Every error is a SceneError "file:line:column: path: message" (scene_error.hpp):
// a syntax error, an unknown key (with "did you mean"), a wrong type, a value out of
// range, a material that does not exist, a degenerate shape, a light that gives no
// light, a scene with nothing in it, a bad OBJ file. A camera inside a sphere is
// allowed but warned about.

// A polygon as read: a "quads" or "polygons" entry or a face of a mesh.
struct FilePolygon {
  FlatPolygon shape;
  int material = 0;
  std::string name;         // its "name", or where it stands: "polygons[3]", "room.obj:17"
  bool from_quads = false;  // a quad or a box's face: the ray tracer has it in Scene::quads already
};

struct SceneFile {
  std::string file;  // as the user named it, for messages
  Scene scene;       // everything but the polygons and meshes
  std::vector<FilePolygon> polygons;  // the boxes' faces, the quads, the polygons, every mesh's faces
  // Where the first sphere and plane stand: radiosity refuses them.
  std::optional<FileLocation> first_sphere, first_plane;
  std::vector<std::string> warnings;  // in the errors' format
};

// What a scene file may make a lesson read, and how much.
//
// Meshes: a scene file names OBJ files, and a scene file may come from anyone (a
// classmate, a download, a hand-in an autograder runs). It reads meshes only from
// below its own folder -- after every "..", and every symbolic link, is followed --
// or from below `mesh_folder` when one is given (a lesson's --mesh-folder DIR), and
// only files whose name ends in .obj. A path outside is refused before anything is
// asked of it, so the message does not even say whether the file exists.
//
// What a message quotes: a scene file's errors show one character at the error's
// position, an OBJ file's the word at fault (at most 40 characters; a line's first
// word only when it has an OBJ keyword's shape, obj_file.cpp): both are files
// the user named, on the command line or in the scene file, and passed the checks
// above. Nothing is ever quoted from any other file.
//
// Size: `max_polygons` bounds the quads, boxes' faces, polygons and mesh faces of the
// scene together, counted as they are read, so that reading stops at the limit rather
// than after a million faces have been stored (a radiosity lesson passes the most
// surfaces it solves for, each polygon being one surface at least).
struct SceneFileRules {
  std::filesystem::path mesh_folder;  // empty: meshes from below the scene file's folder only
  std::size_t max_polygons = 1'000'000;
};

// Reads and checks a scene file (and the OBJ files it names). Throws SceneError.
SceneFile read_scene_file(const std::filesystem::path& file, const SceneFileRules& rules = {});
// The same for text already read: `file` names it in messages, and OBJ paths are
// relative to its folder.
SceneFile read_scene_text(const std::string& text, const std::filesystem::path& file,
                          const SceneFileRules& rules = {});

// The ray tracer's scene: the file's scene with its polygons added as triangles, a
// quadrilateral c0 c1 c2 c3 as (c0, c1, c2) and (c0, c2, c3). Adds a warning if no
// light lights it.
Scene ray_tracing_scene(const SceneFile& file, std::vector<std::string>& warnings);

// --scene NAME|FILE: a value ending in ".json" or holding a '/' names a file.
bool names_a_file(const std::string& choice);

// A built-in scene by name (builtin_scenes.hpp) or a scene file, for the ray tracer.
// Throws std::invalid_argument for an unknown name, SceneError for a bad file.
Scene load_scene(const std::string& choice, std::vector<std::string>& warnings, const SceneFileRules& rules = {});

}  // namespace gi
