#include "gi/core/platform/folder_lock.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include "gi/core/atomic_file.hpp"

#if defined(_WIN32)
#include <windows.h>

#include <cwctype>

#include "gi/core/hash.hpp"
#else
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#endif

namespace gi::platform {

#if defined(_WIN32)

// A folder cannot be locked as a file can on Windows; a mutex named after the folder's
// full path (lower case: the file system ignores case) stands in. The name is a hash:
// a mutex's name may not hold a backslash. An owner that ends without letting go leaves
// the mutex "abandoned", which the next waiter gets.
FolderLock::FolderLock(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw WriteError("cannot lock " + folder.string() + ": " + std::strerror(ENOENT));
  std::wstring path = std::filesystem::weakly_canonical(folder, error).wstring();
  for (wchar_t& c : path) c = static_cast<wchar_t>(std::towlower(c));
  const std::string key = hex(fnv1a({reinterpret_cast<const char*>(path.data()), path.size() * sizeof(wchar_t)}));
  const std::wstring name = L"Local\\gi-workbench-folder-" + std::wstring(key.begin(), key.end());
  const HANDLE mutex = ::CreateMutexW(nullptr, FALSE, name.c_str());
  if (!mutex) throw WriteError("cannot lock " + folder.string() + ": " + std::strerror(EACCES));
  const DWORD waited = ::WaitForSingleObject(mutex, INFINITE);
  if (waited != WAIT_OBJECT_0 && waited != WAIT_ABANDONED) {
    ::CloseHandle(mutex);
    throw WriteError("cannot lock " + folder.string() + ": " + std::strerror(EIO));
  }
  handle_ = reinterpret_cast<std::intptr_t>(mutex);
}

FolderLock::~FolderLock() {
  const auto mutex = reinterpret_cast<HANDLE>(handle_);
  ::ReleaseMutex(mutex);
  ::CloseHandle(mutex);
}

#else

// An exclusive flock(2) on the folder itself: no lock file is left behind, and the
// system drops the lock when the descriptor closes, at the latest as the process ends.
FolderLock::FolderLock(const std::filesystem::path& folder) {
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) throw WriteError("cannot lock " + folder.string() + ": " + std::strerror(errno));
  while (::flock(descriptor, LOCK_EX) != 0)
    if (errno != EINTR) {
      const int error = errno;
      ::close(descriptor);
      throw WriteError("cannot lock " + folder.string() + ": " + std::strerror(error));
    }
  handle_ = descriptor;
}

FolderLock::~FolderLock() { ::close(static_cast<int>(handle_)); }  // closing releases the lock

#endif

}  // namespace gi::platform
