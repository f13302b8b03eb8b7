#pragma once
// A lock on a folder, held by one object at a time across threads and processes, and
// given up when the object goes, or when its process ends however it ends: so that
// lessons finishing together update the index of their folder one after another. The
// one file that knows how, on POSIX (Linux, macOS) and on Windows.
#include <cstdint>
#include <filesystem>

namespace gi::platform {

class FolderLock {
 public:
  // Waits for the lock; throws WriteError (gi/core/atomic_file.hpp) if the folder
  // cannot be opened (it does not exist, or may not be read).
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  // POSIX: the folder's descriptor, flock(2)ed. Windows: the handle of a mutex named
  // after the folder's full path, which the system releases when its owner ends.
  std::intptr_t handle_ = -1;
};

}  // namespace gi::platform
