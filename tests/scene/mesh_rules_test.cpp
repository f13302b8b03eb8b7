// What a scene file may make a lesson read (SceneFileRules, scene_file.hpp): meshes
// from below its own folder only, OBJ files only, nothing quoted from any other file,
// and its polygons counted as they are read, so that a limit stops the reading.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gi/scene/scene_file.hpp"
#include "scene_file_support.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::camera;
using gi_test::matte;
using gi_test::write_text;

const std::string square_obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl white\nf 1 2 3 4\n";

// A scene file in `folder`/scene/room.json whose one mesh is `file`.
fs::path scene_with_mesh(const fs::path& folder, const std::string& file) {
  fs::create_directories(folder / "scene");
  return write_text(folder / "scene" / "room.json",
                    "{" + camera + ", " + matte + R"(, "meshes": [{"file": ")" + file + R"("}]})");
}

std::string error_of(const fs::path& scene, const gi::SceneFileRules& rules = {}) {
  try {
    (void)gi::read_scene_file(scene, rules);
  } catch (const gi::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshRules, AMeshOutsideTheScenesFolderIsRefusedUnasked) {
  const fs::path folder = gi_test::scratch_folder("outside");
  write_text(folder / "secret.obj", square_obj);
  write_text(folder / "scene" / "inside.obj", (fs::create_directories(folder / "scene"), square_obj));
  const std::string at = (folder / "scene" / "room.json").string() + ":1:124: meshes[0].file: ";
  const std::string refused = "a mesh must lie below the scene file's folder (--mesh-folder DIR allows another): ";
  // Up and out, by "..", by an absolute path, and by a link that points out.
  EXPECT_EQ(error_of(scene_with_mesh(folder, "../secret.obj")), at + refused + (folder / "secret.obj").string());
  // (In the JSON with forward slashes, which Windows reads too: its backslashes would be escapes.)
  EXPECT_EQ(error_of(scene_with_mesh(folder, (folder / "secret.obj").generic_string())),
            at + refused + (folder / "secret.obj").string());
  // Windows lets only an administrator or developer mode make a link; where none can
  // be made, no scene can hold one either.
  std::error_code no_links;
  fs::create_symlink(folder / "secret.obj", folder / "scene" / "link.obj", no_links);
  if (!no_links) {
    EXPECT_EQ(error_of(scene_with_mesh(folder, "link.obj")), at + refused + (folder / "scene" / "link.obj").string());
  }
  // A file outside that does not exist is refused the same way: the message does not
  // tell whether it is there.
  EXPECT_EQ(error_of(scene_with_mesh(folder, "../nothing.obj")), at + refused + (folder / "nothing.obj").string());
  // /etc/shadow and its like: outside, so never opened, never quoted. Named as the
  // scene reader resolves it: on Windows, on the scene file's drive (C:\etc\shadow).
  const std::string etc_shadow = (folder.root_name() / "/etc/shadow").lexically_normal().string();
  const std::string shadow = error_of(scene_with_mesh(folder, "/etc/shadow"));
  EXPECT_EQ(shadow, at + refused + etc_shadow);
  // Inside, through a ".." that comes back, is read.
  EXPECT_EQ(error_of(scene_with_mesh(folder, "../scene/inside.obj")), "");
  // --mesh-folder allows one more folder.
  gi::SceneFileRules rules;
  rules.mesh_folder = folder;
  EXPECT_EQ(error_of(scene_with_mesh(folder, "../secret.obj"), rules), "");
  EXPECT_EQ(error_of(scene_with_mesh(folder, "/etc/shadow"), rules),
            at + "a mesh must lie below the scene file's folder or below " + folder.string() +
                " (--mesh-folder DIR allows another): " + etc_shadow);
}

TEST(MeshRules, AMeshIsAnObjFile) {
  const fs::path folder = gi_test::scratch_folder("not_obj");
  fs::create_directories(folder / "scene");
  write_text(folder / "scene" / "notes.txt", "root:x:0:0:the first line of a file that is not OBJ\n");
  const std::string message = error_of(scene_with_mesh(folder, "notes.txt"));
  EXPECT_EQ(message, (folder / "scene" / "room.json").string() +
                         ":1:124: meshes[0].file: a mesh is an OBJ file, its name ending in .obj: " +
                         (folder / "scene" / "notes.txt").string());
  EXPECT_EQ(message.find("root:x"), std::string::npos) << "quoted a file that is not a mesh";
  write_text(folder / "scene" / "upper.OBJ", square_obj);
  EXPECT_EQ(error_of(scene_with_mesh(folder, "upper.OBJ")), "");
}

// 10^6 faces and a limit of 3 000 polygons: the reading stops at face 3 001 (line
// 3 005, the line the error names), not after the whole file has been stored (11 s
// and 1.1 GB for a radiosity lesson, whose surface limit then refused it).
TEST(MeshRules, ReadingStopsAtThePolygonLimit) {
  const fs::path folder = gi_test::scratch_folder("limit");
  fs::create_directories(folder / "scene");
  std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl white\n";
  obj.reserve(8'100'000);
  for (int i = 0; i < 1'000'000; ++i) obj += "f 1 2 3\n";
  write_text(folder / "scene" / "huge.obj", obj);
  gi::SceneFileRules rules;
  rules.max_polygons = 3000;
  EXPECT_EQ(error_of(scene_with_mesh(folder, "huge.obj"), rules),
            (folder / "scene" / "huge.obj").string() +
                ":3005:1: f: more than 3000 polygons (quads, boxes' faces, polygons and mesh faces together), the "
                "most this lesson takes");
  // Quads and boxes count too.
  rules.max_polygons = 5;
  const fs::path box = write_text(folder / "box.json", "{" + camera + ", " + matte +
                                                          R"(, "boxes": [{"min": [0, 0, 0], "max": [1, 1, 1], "material": "white"}]})");
  EXPECT_EQ(error_of(box, rules), box.string() + ":1:114: boxes[0]: more than 5 polygons (quads, boxes' faces, "
                                                 "polygons and mesh faces together), the most this lesson takes");
}
