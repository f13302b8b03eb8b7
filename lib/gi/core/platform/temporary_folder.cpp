#include "gi/core/platform/temporary_folder.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#if defined(_WIN32)
#include <chrono>
#include <random>
#else
#include <stdlib.h>  // mkdtemp
#endif

namespace gi::platform {

namespace fs = std::filesystem;

#if defined(_WIN32)

// Windows has no mkdtemp; create_directory is the same test-and-make in one step,
// false if a folder of that name is there already (another program's), so a new name
// is drawn until one is free.
TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  std::error_code error;
  const fs::path base = fs::temp_directory_path(error);
  if (error) throw std::runtime_error("cannot find the temporary folder: " + error.message());
  std::random_device device;
  std::minstd_rand draw(device() ^ static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count()));
  const char letters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = prefix;
    for (int k = 0; k < 6; ++k) name += letters[draw() % (sizeof letters - 1)];
    if (fs::create_directory(base / name, error)) {
      path_ = base / name;
      return;
    }
    if (error) break;
  }
  throw std::runtime_error("cannot make a temporary folder " + (base / (prefix + "XXXXXX")).string() + ": " +
                           (error ? error.message() : std::string("every name tried was taken")));
}

#else

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  std::error_code error;
  std::string pattern = (fs::temp_directory_path(error) / (prefix + "XXXXXX")).string();
  if (error || !::mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a temporary folder " + pattern + ": " +
                             (error ? error.message() : std::string(std::strerror(errno))));
  path_ = pattern;
}

#endif

TemporaryFolder::~TemporaryFolder() {
  std::error_code error;
  fs::remove_all(path_, error);  // nothing to do about a failure while leaving
}

}  // namespace gi::platform
