#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gi/scene/scene_error.hpp"

namespace gi {

// The syntax layer of the scene reader: JSON (RFC 8259) into a tree in which every
// value remembers the line and column where it starts, so that the schema layer
// (scene_file.hpp) can point at the value it refuses. Debian 12's nlohmann-json
// (3.11.2) gives positions for syntax errors only, hence this reader: one pass over
// the text, no dependency, every error a SceneError naming its position.

struct JsonMember;

struct JsonValue {
  enum class Kind { Null, Boolean, Number, String, Array, Object };
  Kind kind = Kind::Null;
  int line = 1, column = 1;
  bool boolean = false;
  double number = 0;                // finite: JSON has no NaN or infinity, and 1e999 is refused
  std::string text;                 // a String, unescaped (UTF-8)
  std::vector<JsonValue> items;     // an Array
  std::vector<JsonMember> members;  // an Object, in the file's order (duplicates kept: the schema refuses them)
};

struct JsonMember {
  std::string key;
  int line = 1, column = 1;  // of the key
  JsonValue value;
};

// "a number", "an array" ...: for messages.
std::string kind_name(JsonValue::Kind kind);

// "16 MiB", or "64 bytes" for a size that is not a whole number of MiB: for messages.
std::string size_text(std::uintmax_t bytes);

// What a hostile file cannot make the reader do: read past these, it stops with an
// error, so that time and memory stay bounded (about 100 bytes per value).
struct JsonLimits {
  std::size_t max_bytes = 16u << 20;  // 16 MiB: meshes belong in OBJ files
  std::size_t max_values = 1'000'000;
  int max_depth = 64;  // arrays and objects inside each other
};

// Parses the whole text (UTF-8; a leading byte-order mark is skipped). Throws
// SceneError "file:line:column: message" at the first error: bytes that are not
// UTF-8, a syntax error, a number out of the range of a double, NaN or Infinity
// (not JSON), a control character in a string, text after the value, a limit passed.
JsonValue parse_json(std::string_view text, const std::string& file, const JsonLimits& limits = {});

}  // namespace gi
