#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/scene/json.hpp"

namespace gi {

// Typed reading of a scene file's JSON tree (json.hpp): each refusal is a SceneError
// at the position of the value refused, naming its path in the tree:
//   box.json:14:9: materials[2].ior: must be > 0, got -1.5
class SchemaReader {
 public:
  explicit SchemaReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  FileLocation where(const JsonValue& at, const std::string& path) const { return {file_, at.line, at.column, path}; }
  [[noreturn]] void fail(const JsonValue& at, const std::string& path, const std::string& message) const {
    throw SceneError(where(at, path), message);
  }
  // A warning in the errors' format, for the lesson to print.
  std::string warning(const JsonValue& at, const std::string& path, const std::string& message) const {
    return SceneError(where(at, path), message).what();
  }

  // The members of an object, by key. Refuses what is not an object, a key not among
  // `keys` (with the nearest as "did you mean"), a key given twice and a required key
  // missing. Every object may also have an "about": a note for readers, ignored.
  struct Key {
    std::string_view name;
    bool required = false;
  };
  class Fields {
   public:
    const JsonValue* operator[](std::string_view key) const;  // nullptr if absent
   private:
    friend class SchemaReader;
    std::vector<std::pair<std::string_view, const JsonValue*>> members_;
  };
  Fields object(const JsonValue& v, const std::string& path, const std::vector<Key>& keys) const;

  const std::vector<JsonValue>& array(const JsonValue& v, const std::string& path) const;
  std::string text(const JsonValue& v, const std::string& path) const;  // not empty
  // A number in [min, max], or in (min, max] when `above_min` (the message then says
  // "must be > min").
  double number(const JsonValue& v, const std::string& path, double min, double max, bool above_min = false) const;
  // A point or a direction [x, y, z], each within [-1e6, 1e6] scene units: larger
  // values leave too few digits for the ray tracer's epsilons.
  vec3 point(const JsonValue& v, const std::string& path) const;
  // A colour [r, g, b], or one number for a grey, each in [0, 1e6].
  Color colour(const JsonValue& v, const std::string& path) const;

 private:
  std::string file_;
};

// "materials[2]" and "materials[2].ior": paths in the tree, for messages.
inline std::string item_path(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}
inline std::string member_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

// A number as a message shows it: "-1.5", "1e+300".
std::string number_text(double v);

// The largest coordinate a scene file may hold, in scene units.
inline constexpr double max_coordinate = 1e6;

}  // namespace gi
