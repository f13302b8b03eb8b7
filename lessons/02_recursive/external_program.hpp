#pragma once
// Another program for a benchmark (02_tachyon_bench runs Tachyon): found on PATH as a
// POSIX shell would find it, and named with the Debian package that installed it. It
// is run by gi/core/platform/program.hpp. POSIX only, as the bench is.
#include <filesystem>
#include <optional>
#include <string>

namespace gi {

// The first executable file called `program` in the folders of $PATH; none if PATH
// is unset or no folder holds one.
std::optional<std::filesystem::path> find_on_path(const std::string& program);

// "tachyon-bin-nox 0.99~b6+dsx-10+b1": the Debian package that installed `program`
// and its version, as dpkg-query tells them. Symbolic links are followed first:
// /usr/bin/tachyon is an alternative, a link to /usr/bin/tachyon-nox, which the
// package owns. Empty when no package owns it or dpkg-query is not on PATH.
std::string debian_package_of(const std::filesystem::path& program);

}  // namespace gi
