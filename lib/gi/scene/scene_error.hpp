#pragma once
#include <stdexcept>
#include <string>

#include "gi/scene/utf8.hpp"

namespace gi {

// Where something stands in a scene file: the file as the user named it, a 1-based
// line and column (columns count characters, as an editor does), and the path of the
// value in the file's tree, "materials[2].ior" (empty for a syntax error).
struct FileLocation {
  std::string file;
  int line = 1;
  int column = 1;
  std::string path;
};

// A bad scene file. The message is one line in the compilers' format, file first, so
// that an editor can jump to it:
//   lessons/scenes/box.json:14:9: materials[2].ior: must be > 0, got -1.5
// It is std::invalid_argument: bad input, which a lesson refuses with status 2. What it
// quotes of the input is made printable (utf8.hpp): a name holding "\n" or a NUL
// must not split or cut the line.
struct SceneError : std::invalid_argument {
  SceneError(const FileLocation& where, const std::string& message)
      : std::invalid_argument(printable(where.file + ":" + std::to_string(where.line) + ":" +
                                        std::to_string(where.column) + ": " +
                                        (where.path.empty() ? "" : where.path + ": ") + message)) {}
  // A file that cannot be read at all has no position: "box.json: cannot open ...".
  SceneError(const std::string& file, const std::string& message)
      : std::invalid_argument(printable(file + ": " + message)) {}
};

}  // namespace gi
