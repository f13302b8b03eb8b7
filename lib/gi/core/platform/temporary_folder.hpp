#pragma once
// A folder of one's own in the system's temporary folder, gone when done with.
#include <filesystem>
#include <string>

namespace gi::platform {

// A new, empty folder in the system's temporary folder ($TMPDIR, else /tmp; on
// Windows %TEMP%), named `prefix` and six random characters, removed with all it
// holds when this object goes, however the program leaves the scope. Throws
// std::runtime_error if it cannot be made.
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

}  // namespace gi::platform
