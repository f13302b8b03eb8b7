// The schema layer: what a scene file becomes, and one test per message it gives,
// the whole line compared (as Mitsuba's parser tests do).
#include "gi/scene/scene_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "scene_file_support.hpp"

namespace {

using gi::vec3;
using gi_test::camera;
using gi_test::matte;
using gi_test::scene_error;

// A scene with a camera, one material "white" and whatever `rest` adds.
std::string with(const std::string& rest) { return "{" + camera + ", " + matte + (rest.empty() ? "" : ", " + rest) + "}"; }

}  // namespace

TEST(SceneFile, ReadsEveryKindOfPrimitiveInTheDocumentedOrder) {
  const auto folder = gi_test::scratch_folder("every_kind");
  gi_test::write_text(folder / "m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl white\nf 1 2 3 4\nf 1 2 3\n");
  gi_test::write_text(folder / "all.json", R"({
    "name": "all", "camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov": 50},
    "background": [0.1, 0.2, 0.3], "ambient_light": 0.5,
    "materials": [{"name": "white", "diffuse": 0.7, "ambient": 0.1, "specular": [0.1, 0.2, 0.3], "shininess": 20,
                   "mirror": 0.5, "transmission": 0.9, "ior": 1.33, "emission": 2, "checker_size": 0.25,
                   "checker_diffuse": [0, 0, 1], "about": "every key"}],
    "spheres": [{"center": [1, 2, 3], "radius": 0.5, "material": "white"}],
    "planes": [{"point": [0, 0, 0], "normal": [0, 2, 0], "material": "white"}],
    "boxes": [{"min": [0, 0, 0], "max": [1, 2, 3], "material": "white"}],
    "quads": [{"corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0], "material": "white", "name": "q"}],
    "polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "white"}],
    "meshes": [{"file": "m.obj"}],
    "point_lights": [{"position": [0, 5, 0], "intensity": [1, 0.5, 0.25]}],
    "quad_lights": [{"corner": [0, 4, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "intensity": 1}]
  })");
  const gi::SceneFile file = gi::read_scene_file(folder / "all.json");
  const gi::Scene& s = file.scene;
  EXPECT_EQ(s.name, "all");
  EXPECT_EQ(s.camera.vertical_fov, 50);
  EXPECT_EQ(s.background, vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(s.ambient_light, vec3(0.5));
  ASSERT_EQ(s.materials.size(), 1u);
  const gi::Material& m = s.materials[0];
  EXPECT_EQ(m.diffuse, vec3(0.7));
  EXPECT_EQ(m.specular, vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(m.ior, 1.33);
  EXPECT_EQ(m.checker_size, 0.25);
  EXPECT_EQ(m.emission, vec3(2));
  EXPECT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.planes[0].normal, vec3(0, 1, 0));  // normalised
  EXPECT_EQ(s.quads.size(), 7u);                 // the box's six faces, then the quad
  EXPECT_EQ(s.quads[6].corner, vec3(0));
  EXPECT_EQ(s.lights[0].intensity, vec3(1, 0.5, 0.25));
  EXPECT_EQ(s.area_lights.size(), 1u);
  // Radiosity's polygons: six box faces, the quad, the triangle, the mesh's quad and triangle.
  ASSERT_EQ(file.polygons.size(), 10u);
  EXPECT_EQ(file.polygons[5].name, "boxes[0]");
  EXPECT_EQ(file.polygons[6].name, "q");
  EXPECT_TRUE(file.polygons[6].from_quads);
  EXPECT_EQ(file.polygons[7].name, "polygons[0]");
  EXPECT_EQ(file.polygons[7].shape.count, 3);
  EXPECT_EQ(file.polygons[8].name, (folder / "m.obj").string() + ":6");
  EXPECT_EQ(file.polygons[9].shape.count, 3);
  // The ray tracer's: quads stay quads, the triangle is one triangle, the mesh's quad two.
  std::vector<std::string> warnings;
  const gi::Scene traced = gi::ray_tracing_scene(file, warnings);
  EXPECT_EQ(traced.triangles.size(), 4u);
  EXPECT_EQ(traced.triangles[1].c, vec3(1, 1, 0));  // (c0, c1, c2) of the mesh's quad
  EXPECT_EQ(traced.triangles[2].c, vec3(0, 1, 0));  // (c0, c2, c3)
  EXPECT_TRUE(warnings.empty());
}

TEST(SceneFile, TheNameDefaultsToTheFilesStemAndTheCameraToItsDefaults) {
  const auto folder = gi_test::scratch_folder("defaults");
  gi_test::write_text(folder / "little room.json", with(R"("spheres": [{"center": [0, 1, 0], "radius": 1, "material": "white"}])"));
  const gi::SceneFile file = gi::read_scene_file(folder / "little room.json");
  EXPECT_EQ(file.scene.name, "little room");
  EXPECT_EQ(file.scene.camera.up, vec3(0, 1, 0));
  EXPECT_EQ(file.scene.camera.vertical_fov, 45);
  EXPECT_EQ(file.scene.background, vec3(0));
}

// Every message of the schema, whole.
TEST(SceneFile, EveryErrorNamesLineColumnAndField) {
  const std::string sphere = R"("spheres": [{"center": [0, 1, 0], "radius": 1, "material": "white"}])";
  const std::pair<std::string, std::string> cases[] = {
      {"[]", "box.json:1:1: expected an object {...}, got an array"},
      {"{" + camera + "}", "box.json:1:1: the scene has nothing in it: add spheres, planes, quads, polygons or meshes"},
      {"{" + matte + ", " + sphere + "}", "box.json:1:1: missing the key \"camera\""},
      {with("\"sphere\": []"), "box.json:1:104: unknown key \"sphere\" (did you mean \"spheres\"?)"},
      {with("\"lights\": []"), "box.json:1:104: unknown key \"lights\""},
      {with(sphere + ", \"spheres\": []"),
       "box.json:1:174: the key \"spheres\" is given twice"},
      {with(R"("spheres": [{"centre": [0, 1, 0], "radius": 1, "material": "white"}])"),
       "box.json:1:117: spheres[0]: unknown key \"centre\" (did you mean \"center\"?)"},
      {with(R"("spheres": [{"center": [0, 1, 0], "radius": -1.5, "material": "white"}])"),
       "box.json:1:148: spheres[0].radius: must be > 0, got -1.5"},
      {with(R"("spheres": [{"center": [0, 1], "radius": 1, "material": "white"}])"),
       "box.json:1:127: spheres[0].center: expected three numbers [x, y, z], got 2 items"},
      {with(R"("spheres": [{"center": [0, 1e300, 0], "radius": 1, "material": "white"}])"),
       "box.json:1:131: spheres[0].center[1]: must be at most 1e+06, got 1e+300"},
      {with(R"("spheres": [{"center": [0, 1, 0], "radius": "1", "material": "white"}])"),
       "box.json:1:148: spheres[0].radius: expected a number, got a string"},
      {with(R"("spheres": [{"center": [0, 1, 0], "radius": 1, "material": "whit"}])"),
       "box.json:1:163: spheres[0].material: no material is named 'whit' (did you mean 'white'?)"},
      {with(R"("spheres": [{"center": [0, 1, 0], "radius": 1}])"), "box.json:1:116: spheres[0]: missing the key \"material\""},
      {with(R"("spheres": {})"), "box.json:1:115: spheres: expected an array [...], got an object"},
      {"{" + camera + R"(, "materials": [{"name": "white"}, {"name": "white"}])" + ", " + sphere + "}",
       "box.json:1:96: materials[1].name: 'white' is the name of materials[0] already"},
      {"{" + camera + R"(, "materials": [{"name": "glass", "transmission": 1, "ior": -1.5}])" + "}",
       "box.json:1:112: materials[0].ior: must be > 0, got -1.5"},
      {"{" + camera + R"(, "materials": [{"name": "m", "diffuse": [1, -0.5, 1]}])" + "}",
       "box.json:1:97: materials[0].diffuse[1]: must be >= 0, got -0.5"},
      {"{" + camera + R"(, "materials": [{"name": ""}])" + "}", "box.json:1:77: materials[0].name: must not be empty"},
      {"{" + camera + R"(, "materials": [{"name": "m", "about": 3}])" + "}",
       "box.json:1:91: materials[0].about: expected a string in double quotes, got a number"},
      {with(R"("quads": [{"corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [2, 0, 0], "material": "white"}])"),
       "box.json:1:114: quads[0]: the edges are zero or parallel, so the quad has no area"},
      {with(R"("boxes": [{"min": [0, 0, 0], "max": [1, 0, 1], "material": "white"}])"),
       "box.json:1:140: boxes[0].max: must exceed min on every axis"},
      {with(R"("planes": [{"point": [0, 0, 0], "normal": [0, 0, 0], "material": "white"}])"),
       "box.json:1:146: planes[0].normal: must not be [0, 0, 0]"},
      {with(R"("polygons": [{"corners": [[0, 0, 0], [1, 0, 0]], "material": "white"}])"),
       "box.json:1:129: polygons[0].corners: a polygon has 3 or 4 corners, got 2 (cut larger polygons into triangles "
       "and quadrilaterals)"},
      {with(R"("polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]], "material": "white"}])"),
       "box.json:1:129: polygons[0].corners: the corners are not in one plane (a corner is 7.9% of its size off it; "
       "at most 1%)"},
      {with(R"("polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0.2, 0.2, 0], [0, 1, 0]], "material": "white"}])"),
       "box.json:1:129: polygons[0].corners: the corners do not make a convex quadrilateral (list them in order "
       "around it)"},
      {with(R"("polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "material": "white"}])"),
       "box.json:1:129: polygons[0].corners: the corners are on one line, so it has no area"},
      {with(sphere + R"(, "point_lights": [{"position": [0, 5, 0], "intensity": [0, 0, 0]}])"),
       "box.json:1:228: point_lights[0].intensity: a light must give light, got 0"},
      {with(sphere + R"(, "quad_lights": [{"corner": [0, 5, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 0], "intensity": 1}])"),
       "box.json:1:190: quad_lights[0]: the edges are zero or parallel, so the quad has no area"},
      {with(R"("meshes": [{"file": "nowhere.obj", "material": "white"}])"),
       "box.json:1:124: meshes[0].file: no such file: " + (gi_test::scratch_folder("error") / "nowhere.obj").string()},
      {R"({"camera": {"eye": [0, 1, 5], "look_at": [0, 1, 5]}, )" + matte + ", " + sphere + "}",
       "box.json:1:12: camera: eye and look_at must differ"},
      {R"({"camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0], "up": [0, 0, 1]}, )" + matte + ", " + sphere + "}",
       "box.json:1:12: camera: up must not be parallel to the view direction"},
      {R"({"camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0], "fov": 180}, )" + matte + ", " + sphere + "}",
       "box.json:1:60: camera.fov: must be < 180, got 180"},
      {R"({"camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0], "fov": 0}, )" + matte + ", " + sphere + "}",
       "box.json:1:60: camera.fov: must be > 0, got 0"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(scene_error(text), message) << "file: " << text;
}

TEST(SceneFile, UnreadableFilesSayWhy) {
  const auto folder = gi_test::scratch_folder("unreadable");
  try {
    (void)gi::read_scene_file(folder / "missing.json");
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), (folder / "missing.json").string() + ": no such file");
  }
  try {
    (void)gi::read_scene_file(folder);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), folder.string() + ": not a file one can read a scene from");
  }
  // Larger than the limit: refused by its size, unread.
  std::filesystem::resize_file(gi_test::write_text(folder / "huge.json", ""), (16u << 20) + 1);
  EXPECT_THROW((void)gi::read_scene_file(folder / "huge.json"), gi::SceneError);
}

TEST(SceneFile, ACameraInsideASphereIsWarnedAboutAndNoLightsAreWarnedAbout) {
  const auto folder = gi_test::scratch_folder("inside");
  gi_test::write_text(folder / "inside.json", "{" + camera + ", " + matte + R"(, "spheres": [
    {"center": [0, 1, 0], "radius": 1, "material": "white"},
    {"center": [0, 1, 4], "radius": 2, "material": "white"}]})");
  const gi::SceneFile file = gi::read_scene_file(folder / "inside.json");
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_EQ(file.warnings[0], (folder / "inside.json").string() +
                                  ":1:12: camera.eye: inside spheres[1]: the picture shows its inside");
  std::vector<std::string> warnings;
  (void)gi::ray_tracing_scene(file, warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[1], (folder / "inside.json").string() +
                             ": no point_lights or quad_lights, which are what light the ray tracer's scene: it shows "
                             "only what emits and the ambient light");
}

TEST(SceneFile, ChoicesNameAFileOrABuiltInScene) {
  EXPECT_TRUE(gi::names_a_file("room.json"));
  EXPECT_TRUE(gi::names_a_file("ROOM.JSON"));
  EXPECT_TRUE(gi::names_a_file("scenes/room"));
  EXPECT_FALSE(gi::names_a_file("whitted"));
  EXPECT_FALSE(gi::names_a_file(".json"));
  std::vector<std::string> warnings;
  EXPECT_EQ(gi::load_scene("whitted", warnings).name, "whitted");
  try {
    (void)gi::load_scene("whited", warnings);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "unknown scene 'whited' (did you mean 'whitted'?); built-in scenes: whitted, "
                                     "spheres, s10, aliasing, soft; or a scene file ending in .json");
  }
}

// A file may name many materials, and an OBJ many usemtl names: looking them up must
// not cost a search through all of them per shape. With 200 000 materials a search
// per name would make 2 x 10^10 string comparisons (minutes; the test then fails by
// ctest's timeout); by map, it reads in well under a second.
TEST(SceneFile, ManyMaterialsAreLookedUpByName) {
  std::string materials = "\"materials\": [";
  const int count = 200'000;
  for (int i = 0; i < count; ++i) materials += (i ? ", " : "") + std::string("{\"name\": \"m") + std::to_string(i) + "\"}";
  materials += "]";
  std::string spheres = "\"spheres\": [";
  for (int i = 0; i < 1000; ++i)
    spheres += (i ? ", " : "") + std::string(R"({"center": [0, 0, -5], "radius": 1, "material": "m)") +
               std::to_string(count - 1 - i) + "\"}";
  spheres += "]";
  const auto folder = gi_test::scratch_folder("many_materials");
  const std::string text = "{" + camera + ", " + materials + ", " + spheres + "}";
  const gi::SceneFile file = gi::read_scene_text(text, folder / "many.json");
  ASSERT_EQ(file.scene.materials.size(), static_cast<std::size_t>(count));
  EXPECT_EQ(file.scene.spheres.back().material, count - 1000);
  std::string duplicate = text;
  duplicate.replace(duplicate.find("\"m1\""), 4, "\"m0\"");
  EXPECT_EQ(scene_error(duplicate), "box.json:1:93: materials[1].name: 'm0' is the name of materials[0] already");
}
