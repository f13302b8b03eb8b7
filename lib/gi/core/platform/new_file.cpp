#include "gi/core/platform/new_file.hpp"

#include <cerrno>

#if defined(_WIN32)
#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#include <windows.h>

#include <chrono>
#include <thread>
#else
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#endif

namespace gi::platform {

#if defined(_WIN32)

int open_new_file(const std::filesystem::path& file) {
  return ::_wopen(file.c_str(), _O_WRONLY | _O_CREAT | _O_TRUNC | _O_BINARY | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
}

long long write_some(int descriptor, const char* data, std::size_t size) {
  const unsigned chunk = size > (1u << 30) ? 1u << 30 : static_cast<unsigned>(size);
  return ::_write(descriptor, data, chunk);
}

int close_file(int descriptor) { return ::_close(descriptor); }

namespace {

int errno_of(DWORD error) {
  switch (error) {
    case ERROR_FILE_NOT_FOUND:
    case ERROR_PATH_NOT_FOUND: return ENOENT;
    case ERROR_ACCESS_DENIED:
    case ERROR_SHARING_VIOLATION:
    case ERROR_LOCK_VIOLATION: return EACCES;
    case ERROR_DISK_FULL:
    case ERROR_HANDLE_DISK_FULL: return ENOSPC;
    case ERROR_WRITE_PROTECT: return EROFS;
    case ERROR_NOT_SAME_DEVICE: return EXDEV;
    default: return EIO;
  }
}

}  // namespace

int replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  // A file another program has open without FILE_SHARE_DELETE cannot be replaced until
  // it lets go; such holds last milliseconds, so the move is tried again for a while.
  for (int attempt = 0;; ++attempt) {
    if (::MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return 0;
    const DWORD error = ::GetLastError();
    if ((error != ERROR_ACCESS_DENIED && error != ERROR_SHARING_VIOLATION) || attempt == 50) return errno_of(error);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

#else

int open_new_file(const std::filesystem::path& file) {
  return ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
}

long long write_some(int descriptor, const char* data, std::size_t size) { return ::write(descriptor, data, size); }

int close_file(int descriptor) { return ::close(descriptor); }

int replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  return std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

#endif

}  // namespace gi::platform
