// The OBJ reader: the faces it reads, and one test per message, whole.
#include "gi/scene/obj_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "scene_file_support.hpp"

namespace {

using gi::vec3;

gi::ObjMesh read(const std::string& text) {
  const auto folder = gi_test::scratch_folder("obj");
  return gi::read_obj(gi_test::write_text(folder / "m.obj", text), "m.obj");
}

std::string error_of(const std::string& text) {
  try {
    (void)read(text);
  } catch (const gi::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ObjFile, FacesWithEveryIndexFormAndMaterialsByName) {
  const gi::ObjMesh mesh = read("# a comment\r\nmtllib room.mtl\no room\nv 0 0 0\nv 1 0 0\nv 1 1 0 1.0\n"
                                "v 0 1 0 0.5 0.5 0.5\nvt 0 0\nvn 0 0 1\ns off\nf 1 2 3\nusemtl wall\n"
                                "f 1/1 2/1 3/1 4/1\ng part\nusemtl floor\nf 1//1 2//1 3//1\nf -4/1/1 -3/1/1 -2/1/1\n"
                                "usemtl wall\nf 2 3 4   # trailing comment\n");
  ASSERT_EQ(mesh.faces.size(), 5u);
  EXPECT_EQ(mesh.material_names, (std::vector<std::string>{"wall", "floor"}));
  EXPECT_EQ(mesh.faces[0].material, -1);
  EXPECT_EQ(mesh.faces[0].line, 11);
  EXPECT_EQ(mesh.faces[1].polygon.count, 4);
  EXPECT_EQ(mesh.faces[1].polygon.corners[3], vec3(0, 1, 0));
  EXPECT_EQ(mesh.faces[1].material, 0);
  EXPECT_EQ(mesh.faces[2].material, 1);
  EXPECT_EQ(mesh.faces[3].polygon.corners[0], vec3(0, 0, 0));  // -4: four vertices back
  EXPECT_EQ(mesh.faces[4].material, 0);
  EXPECT_EQ(mesh.faces[4].polygon.corners[0], vec3(1, 0, 0));
}

TEST(ObjFile, EveryErrorNamesLineAndColumn) {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  const std::pair<std::string, std::string> cases[] = {
      {"", "m.obj:0:1: the file has no faces (f)"},
      {square, "m.obj:4:1: the file has no faces (f)"},
      {"v 0 0\n", "m.obj:1:1: v: expected x y z after v (and at most a weight or a colour)"},
      {"v 0 x 0\n", "m.obj:1:5: v: expected a number, got 'x'"},
      {"v 0 nan 0\n", "m.obj:1:5: v: expected a number, got 'nan'"},
      {"v 0 1e400 0\n", "m.obj:1:5: v: expected a number, got '1e400'"},
      // Decimal text only (number_text.hpp), whatever the converter would take.
      {"v 0 0x10 0\n", "m.obj:1:5: v: expected a number, got '0x10'"},
      {"v 0 +1 0\n", "m.obj:1:5: v: expected a number, got '+1'"},
      {"v 0 inf 0\n", "m.obj:1:5: v: expected a number, got 'inf'"},
      {"v 0 1e 0\n", "m.obj:1:5: v: expected a number, got '1e'"},
      {"v 0 1e-320 0\n", "m.obj:1:5: v: a coordinate must be 0 or at least 2.2250738585072014e-308 in size (a "
                          "smaller double has lost digits), got 1e-320"},
      {"v 0 2e6 0\n", "m.obj:1:5: v: a coordinate must lie in [-1e6, 1e6], got 2e6"},
      {square + "f 1 2\n", "m.obj:5:1: f: a face of 2 corners; only triangles and quadrilaterals (triangulate the "
                           "mesh when you export it)"},
      {square + "f 1 2 3 4 1\n", "m.obj:5:1: f: a face of 5 corners; only triangles and quadrilaterals (triangulate "
                                 "the mesh when you export it)"},
      {square + "f 1 2 5\n", "m.obj:5:7: f: vertex 5 does not exist (4 vertices so far; indices count from 1, or "
                             "back from -1)"},
      {square + "f 0 1 2\n", "m.obj:5:3: f: vertex 0 does not exist (4 vertices so far; indices count from 1, or "
                             "back from -1)"},
      {square + "f -5 1 2\n", "m.obj:5:3: f: vertex -5 does not exist (4 vertices so far; indices count from 1, or "
                              "back from -1)"},
      {square + "f 1 2 a\n", "m.obj:5:7: f: expected a vertex index such as 7, 7/2 or 7//3, got 'a'"},
      {square + "f 1 2 3/x\n", "m.obj:5:7: f: expected a vertex index such as 7, 7/2 or 7//3, got '3/x'"},
      {square + "f 1 2 +3\n", "m.obj:5:7: f: expected a vertex index such as 7, 7/2 or 7//3, got '+3'"},
      {square + "f 1 2 2\n", "m.obj:5:1: f: the corners are on one line, so it has no area"},
      {square + "v 1 1 1\nf 1 2 5 4\n", "m.obj:6:1: f: the corners are not in one plane (a corner is 12% of its "
                                        "size off it; at most 1%)"},
      {square + "f 1 3 2 4\n", "m.obj:5:1: f: the corners span no area"},  // a bow tie: its diagonals are parallel
      {square + "v 0.2 0.2 0\nf 1 2 5 4\n", "m.obj:6:1: f: the corners do not make a convex quadrilateral (list "
                                            "them in order around it)"},
      {square + "usemtl\n", "m.obj:5:1: usemtl: expected one material name after usemtl"},
      {square + "curv 0 1 1 2\n", "m.obj:5:1: 'curv' is not a statement this reader knows (v, f, usemtl; vt, vn, "
                                  "mtllib, o, g, s are skipped): export triangles and quadrilaterals only"},
      {"v 0 0 0\n\xE9t\xE9\n", "m.obj:2:1: the file is not UTF-8 text"},
      // Binary junk: the NUL would have ended the message inside its quote of the word.
      {std::string("v 0 0 0\n\x01\0\xC3\xBF junk\n", 17), "m.obj:2:1: a control character (code 1): the file is not OBJ text"},
      {square + "f 1 2\x1b[31m 3\n", "m.obj:5:6: a control character (code 27): the file is not OBJ text"},
      {square + "usemtl caf\xC3\xA9\r\nf 1 2 3\r\nx\xC3\xA9\r\n",
       "m.obj:7:1: the line begins with no statement this reader knows (v, f, usemtl; vt, vn, mtllib, o, g, s are "
       "skipped): export triangles and quadrilaterals only"},  // CR and UTF-8 are text, but no OBJ keyword
      // A first line that is no keyword is not quoted: the file may be a password file.
      {"root:x:0:0:root:/root:/bin/bash\n", "m.obj:1:1: the line begins with no statement this reader knows (v, f, "
                                            "usemtl; vt, vn, mtllib, o, g, s are skipped): export triangles and "
                                            "quadrilaterals only"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(error_of(text), message) << "file:\n" << text;
}

TEST(ObjFile, LimitsAndMissingFiles) {
  const auto folder = gi_test::scratch_folder("obj_limits");
  const auto file = gi_test::write_text(folder / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n");
  gi::ObjLimits limits;
  limits.max_faces = 1;
  try {
    (void)gi::read_obj(file, "m.obj", limits);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "m.obj:5:1: f: more than 1 faces");
  }
  limits = {};
  limits.max_vertices = 2;
  EXPECT_THROW((void)gi::read_obj(file, "m.obj", limits), gi::SceneError);
  limits = {};
  limits.max_bytes = 10;
  try {
    (void)gi::read_obj(file, "m.obj", limits);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "m.obj: larger than 10 bytes");
  }
  try {
    (void)gi::read_obj(folder / "none.obj", "none.obj");
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "none.obj: no such file");
  }
}

TEST(ObjFile, MeshesInASceneFileTakeTheirMaterialsByName) {
  const auto folder = gi_test::scratch_folder("obj_scene");
  gi_test::write_text(folder / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl whit\nf 1 2 3\n");
  const std::string top = "{" + gi_test::camera + ", " + gi_test::matte + ", \"meshes\": [";
  gi_test::write_text(folder / "a.json", top + "{\"file\": \"m.obj\"}]}");
  const std::string obj = (folder / "m.obj").string();
  try {
    (void)gi::read_scene_file(folder / "a.json");
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), obj + ":4:1: f: no material: put 'usemtl NAME' before it, or give meshes[0] a "
                                           "\"material\"");
  }
  gi_test::write_text(folder / "b.json", top + "{\"file\": \"m.obj\", \"material\": \"white\"}]}");
  try {
    (void)gi::read_scene_file(folder / "b.json");
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), obj + ":6:1: f: its material 'whit' (usemtl) is not among the materials of " +
                                         (folder / "b.json").string() + " (did you mean 'white'?)");
  }
}
