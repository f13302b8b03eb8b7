#include "gi/scene/obj_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <unordered_map>

#include "gi/core/decimal.hpp"
#include "gi/core/number_text.hpp"
#include "gi/scene/json.hpp"
#include "gi/scene/utf8.hpp"

namespace gi {

namespace {

// One word of a line and the column it starts at.
struct Word {
  std::string_view text;
  int column;
};

// The words of a line, up to a '#' comment; columns count characters.
std::vector<Word> words(std::string_view line) {
  std::vector<Word> out;
  int column = 1;
  for (std::size_t i = 0; i < line.size();) {
    const char c = line[i];
    if (c == '#') break;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i, ++column;
      continue;
    }
    const std::size_t start = i;
    const int start_column = column;
    for (; i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#'; ++i)
      column += (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80;
    out.push_back({line.substr(start, i - start), start_column});
  }
  return out;
}

class ObjReader {
 public:
  ObjReader(const std::string& name, const ObjLimits& limits) : name_(name), limits_(limits) {}

  void line(std::string_view text) {
    ++line_;
    if (int bad = 0; !is_utf8(text, &bad)) fail(bad, "", "the file is not UTF-8 text");
    // Nor is a control character text (tab and a Windows line end's CR aside); quoted
    // in the message about an unknown statement, a NUL would have cut the line short.
    int column = 1;
    for (const char c : text) {
      const auto code = static_cast<unsigned char>(c);
      if (code < 0x20 && c != '\t' && c != '\r')
        fail(column, "", "a control character (code " + std::to_string(code) + "): the file is not OBJ text");
      column += (code & 0xC0) != 0x80;
    }
    const std::vector<Word> w = words(text);
    if (w.empty()) return;
    const std::string_view keyword = w[0].text;
    if (keyword == "v") {
      vertex(w);
    } else if (keyword == "f") {
      face(w);
    } else if (keyword == "usemtl") {
      if (w.size() != 2) fail(w[0].column, "usemtl", "expected one material name after usemtl");
      // A map, not a search: a hostile file's million names must not cost 10^12 steps.
      const auto [at, added] = material_index_.try_emplace(std::string(w[1].text), mesh_.material_names.size());
      if (added) mesh_.material_names.push_back(at->first);
      material_ = static_cast<int>(at->second);
    } else if (keyword != "vt" && keyword != "vn" && keyword != "mtllib" && keyword != "o" && keyword != "g" &&
               keyword != "s") {
      std::string what = "the line begins with no statement";
      if (looks_like_a_keyword(keyword)) what = std::string("'").append(keyword).append("' is not a statement");
      fail(w[0].column, "", what + " this reader knows (v, f, usemtl; vt, vn, mtllib, o, g, s are skipped): export "
                                   "triangles and quadrilaterals only");
    }
  }

  ObjMesh finish() {
    if (mesh_.faces.empty()) throw SceneError({name_, line_, 1, ""}, "the file has no faces (f)");
    return std::move(mesh_);
  }

 private:
  // OBJ's statements are short lower-case words (curv, cstype, bmat). A first word of
  // another shape is quoted by no message: the file is perhaps no OBJ file at all, and
  // its first line (a password file's, a key's) is not for a terminal or a log.
  static bool looks_like_a_keyword(std::string_view word) {
    return word.size() <= 16 && word[0] >= 'a' && word[0] <= 'z' &&
           std::all_of(word.begin(), word.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
  }

  [[noreturn]] void fail(int column, const std::string& path, const std::string& message) const {
    throw SceneError({name_, line_, column, path}, message);
  }

  // Decimal text first (number_text.hpp): the grammar, not the converter, says what is a number.
  double number(const Word& w) const {
    double v = 0;
    const auto [end, error] = read_decimal(w.text.data(), w.text.data() + w.text.size(), v);
    if (!is_real_number_text(w.text) || error != std::errc() || end != w.text.data() + w.text.size() ||
        !std::isfinite(v))
      fail(w.column, "v", "expected a number, got '" + std::string(w.text.substr(0, 40)) + "'");
    if (const RealProblem problem = real_problem(v); problem != RealProblem::None)
      fail(w.column, "v", "a coordinate " + real_problem_text(problem) + ", got " + std::string(w.text));
    if (std::abs(v) > 1e6) fail(w.column, "v", "a coordinate must lie in [-1e6, 1e6], got " + std::string(w.text));
    return v;
  }

  void vertex(const std::vector<Word>& w) {
    if (w.size() != 4 && w.size() != 5 && w.size() != 7)
      fail(w[0].column, "v", "expected x y z after v (and at most a weight or a colour)");
    if (vertices_.size() >= limits_.max_vertices)
      fail(w[0].column, "v", "more than " + std::to_string(limits_.max_vertices) + " vertices");
    vertices_.push_back({number(w[1]), number(w[2]), number(w[3])});
    for (std::size_t k = 4; k < w.size(); ++k) (void)number(w[k]);
  }

  // "7", "7/2", "7//3", "7/2/3", "-1": the vertex index before the first slash.
  vec3 corner(const Word& w) const {
    const std::string_view first = w.text.substr(0, w.text.find('/'));
    long long index = 0;
    const auto [end, error] = std::from_chars(first.data(), first.data() + first.size(), index);
    const bool rest_ok = std::all_of(w.text.begin() + static_cast<std::ptrdiff_t>(first.size()), w.text.end(),
                                     [](char c) { return c == '/' || c == '-' || (c >= '0' && c <= '9'); });
    if (!is_whole_number_text(first) || error != std::errc() || end != first.data() + first.size() || !rest_ok)
      fail(w.column, "f",
           "expected a vertex index such as 7, 7/2 or 7//3, got '" + std::string(w.text.substr(0, 40)) + "'");
    const auto n = static_cast<long long>(vertices_.size());
    const long long at = index < 0 ? n + index : index - 1;
    if (index == 0 || at < 0 || at >= n)
      fail(w.column, "f", "vertex " + std::string(first) + " does not exist (" + std::to_string(n) +
                              " vertices so far; indices count from 1, or back from -1)");
    return vertices_[static_cast<std::size_t>(at)];
  }

  void face(const std::vector<Word>& w) {
    const std::size_t corners = w.size() - 1;
    if (corners < 3 || corners > 4)
      fail(w[0].column, "f", "a face of " + std::to_string(corners) + " corners; only triangles and quadrilaterals " +
                                 "(triangulate the mesh when you export it)");
    if (mesh_.faces.size() >= limits_.max_faces)
      fail(w[0].column, "f", limits_.why_max_faces.empty() ? "more than " + std::to_string(limits_.max_faces) + " faces"
                                                           : limits_.why_max_faces);
    ObjFace f;
    f.polygon.count = static_cast<int>(corners);
    for (std::size_t k = 0; k < corners; ++k) f.polygon.corners[k] = corner(w[k + 1]);
    if (const std::string problem = polygon_problem(f.polygon); !problem.empty()) fail(w[0].column, "f", problem);
    f.material = material_;
    f.line = line_;
    mesh_.faces.push_back(f);
  }

  const std::string& name_;
  ObjLimits limits_;
  int line_ = 0;
  int material_ = -1;
  std::unordered_map<std::string, std::size_t> material_index_;
  std::vector<vec3> vertices_;
  ObjMesh mesh_;
};

}  // namespace

ObjMesh read_obj(const std::filesystem::path& file, const std::string& shown_name, const ObjLimits& limits) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw SceneError(shown_name, "no such file");
  if (!std::filesystem::is_regular_file(status)) throw SceneError(shown_name, "not a file one can read a mesh from");
  if (std::filesystem::file_size(file, error) > limits.max_bytes || error)
    throw SceneError(shown_name, "larger than " + size_text(limits.max_bytes));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(shown_name, std::string("cannot open the file (") + std::strerror(errno) + ")");
  return read_obj(in, shown_name, limits);
}

ObjMesh read_obj(std::istream& in, const std::string& shown_name, const ObjLimits& limits) {
  ObjReader reader(shown_name, limits);
  // Lines are read whole; the size check above bounds the longest.
  for (std::string line; std::getline(in, line);) reader.line(line);
  if (in.bad()) throw SceneError(shown_name, "a read error");
  return reader.finish();
}

}  // namespace gi
