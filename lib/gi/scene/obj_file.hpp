#pragma once
#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "gi/scene/flat_polygon.hpp"
#include "gi/scene/scene_error.hpp"

namespace gi {

// A mesh from a Wavefront OBJ file: its faces, each with the material named by the
// `usemtl` before it (the names are looked up among the scene file's materials).
struct ObjFace {
  FlatPolygon polygon;
  int material = -1;  // into ObjMesh::material_names; -1 before any usemtl
  int line = 0;       // where the face is, for messages
};

struct ObjMesh {
  std::vector<std::string> material_names;
  std::vector<ObjFace> faces;
};

struct ObjLimits {
  std::uintmax_t max_bytes = 128u << 20;
  std::size_t max_vertices = 1'000'000;
  std::size_t max_faces = 1'000'000;
  std::string why_max_faces;  // the message when max_faces is passed; "" says "more than N faces"
};

// Reads the part of OBJ a scene needs, line by line:
//   v x y z        a vertex (a fourth number, or three of colour, is ignored)
//   f a b c [d]    a triangle or a quadrilateral, counter-clockwise seen from the
//                  front; each corner is a vertex index from 1 (or negative: -1 is
//                  the last vertex so far), optionally with /texture/normal indices,
//                  which are ignored
//   usemtl NAME    the material of the faces after it
//   vt, vn, mtllib, o, g, s and # comments are read past.
// Every face must pass polygon_problem (flat_polygon.hpp). `shown_name` is the file
// as messages name it. Throws SceneError "name:line:column: f: message" for a file
// that cannot be read, is not UTF-8 text, has a statement it does not know, a number
// it cannot read or larger than 1e6 in size, a vertex index that does not exist yet, a
// face of fewer than 3 or more than 4 corners or one that is not flat and convex, or
// passes a limit. Nothing is guessed: a bad face is an error, never dropped.
ObjMesh read_obj(const std::filesystem::path& file, const std::string& shown_name, const ObjLimits& limits = {});
// The same from a stream (the file's size limit is the caller's).
ObjMesh read_obj(std::istream& in, const std::string& shown_name, const ObjLimits& limits = {});

}  // namespace gi
