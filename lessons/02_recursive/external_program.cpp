#include "external_program.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "gi/core/platform/program.hpp"

namespace gi {

namespace fs = std::filesystem;

std::optional<fs::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string_view folders(path);
  while (true) {
    const std::size_t end = std::min(folders.find(':'), folders.size());
    // An empty entry is the current folder, as POSIX shells read it.
    const fs::path candidate = fs::path(end == 0 ? "." : std::string(folders.substr(0, end))) / program;
    std::error_code error;
    if (fs::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == folders.size()) return std::nullopt;
    folders.remove_prefix(end + 1);
  }
}

std::string debian_package_of(const fs::path& program) {
  const std::optional<fs::path> dpkg_query = find_on_path("dpkg-query");
  std::error_code error;
  const fs::path file = fs::canonical(program, error);
  if (!dpkg_query || error) return "";
  try {
    // "tachyon-bin-nox: /usr/bin/tachyon-nox": the package is what comes before ": ".
    const platform::ProgramRun owner = platform::run_program({dpkg_query->string(), "-S", file.string()}, 30);
    const std::size_t colon = owner.output.find(": ");
    if (owner.status != 0 || colon == std::string::npos) return "";
    const std::string package = owner.output.substr(0, colon);
    const platform::ProgramRun version =
        platform::run_program({dpkg_query->string(), "-W", "-f=${Version}", package}, 30);
    if (version.status != 0 || version.output.empty()) return "";
    return package + " " + version.output;
  } catch (const std::runtime_error&) {
    return "";  // a dpkg-query that hangs or cannot start knows nothing to tell
  }
}

}  // namespace gi
