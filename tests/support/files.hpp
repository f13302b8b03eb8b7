#pragma once
// Files for tests: a small disk made on purpose, and what a folder or a file holds.
#if defined(__linux__)
#include <sys/mount.h>
#include <unistd.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gi_test {

// A file system of a few kilobytes mounted for one test: a full disk, or a read-only
// one, made on purpose (a tmpfs: Linux, and mount(2) needs root). Where it cannot be
// made, mounted() is false and why_not() says why, for GTEST_SKIP.
class SmallDisk {
 public:
  // `kilobytes` of space; read_only: nothing can be written at all.
  explicit SmallDisk(int kilobytes, bool read_only = false) {
#if !defined(__linux__)
    (void)kilobytes, (void)read_only;
    why_not_ = "a small disk is a Linux tmpfs, which this system does not have";
#else
    std::string pattern = (std::filesystem::temp_directory_path() / "gi_small_disk_XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      why_not_ = std::string("cannot make a mount point: ") + std::strerror(errno);
      return;
    }
    path_ = pattern;
    const std::string options = "size=" + std::to_string(kilobytes) + "k";
    if (::mount("tmpfs", path_.c_str(), "tmpfs", read_only ? MS_RDONLY : 0, options.c_str()) != 0) {
      why_not_ = std::string("cannot mount a small tmpfs (needs root): ") + std::strerror(errno);
      return;
    }
    mounted_ = true;
#endif
  }
  ~SmallDisk() {
#if defined(__linux__)
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
#endif
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove(path_, ignored);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;

  bool mounted() const { return mounted_; }
  const std::string& why_not() const { return why_not_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  bool mounted_ = false;
  std::string why_not_;
};

// Files in `folder` (not recursive), names only.
inline std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ignored)) names.push_back(entry.path().filename().string());
  return names;
}

// The whole file, as bytes.
inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace gi_test
