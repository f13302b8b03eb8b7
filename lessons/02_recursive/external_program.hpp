#pragma once
// Running another program from a benchmark (02_tachyon_bench runs Tachyon): found on
// PATH as a shell would find it, its output captured, stopped if it runs too long,
// and named with the Debian package that installed it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gi {

// The first executable file called `program` in the folders of $PATH; none if PATH
// is unset or no folder holds one.
std::optional<std::filesystem::path> find_on_path(const std::string& program);

struct ProgramRun {
  int status;          // its exit status, or -1 if a signal ended it
  std::string output;  // stdout and stderr, in the order written
};

// Runs `program` with `args` directly (no shell: nothing in them is interpreted),
// stdin from /dev/null. Throws std::runtime_error if it cannot be started, or has
// not finished after `time_limit` seconds (it is then killed).
ProgramRun run_program(const std::filesystem::path& program, const std::vector<std::string>& args,
                       double time_limit);

// "tachyon-bin-nox 0.99~b6+dsx-10+b1": the Debian package that installed `program`
// and its version, as dpkg-query tells them. Symbolic links are followed first:
// /usr/bin/tachyon is an alternative, a link to /usr/bin/tachyon-nox, which the
// package owns. Empty when no package owns it or dpkg-query is not on PATH.
std::string debian_package_of(const std::filesystem::path& program);

// A new, empty folder in the system's temporary folder ($TMPDIR, else /tmp), named
// `prefix` and six random characters, removed with all it holds when this object
// goes, however the program leaves the scope. Throws std::runtime_error if it
// cannot be made.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace gi
