#pragma once
// Writing a new file and putting it in place of an old one: the system calls differ
// between POSIX (Linux, macOS) and Windows, and this is the one file that knows both.
// Errors are errno values (ENOSPC, EACCES, EROFS ...), which std::strerror spells.
#include <cstddef>
#include <filesystem>

namespace gi::platform {

// Opens `file` for writing in binary (no line-end translation), created or emptied,
// and not inherited by programs this one starts. Returns a descriptor, or -1 with errno
// set.
int open_new_file(const std::filesystem::path& file);
// Writes up to `size` bytes: how many were written, or -1 with errno set (EINTR: the
// call was interrupted and may be made again).
long long write_some(int descriptor, const char* data, std::size_t size);
// 0, or -1 with errno set: a network file system may report a failed write only here.
int close_file(int descriptor);

// Puts `from` in the place of `to` in one step, replacing `to` if it exists: any reader
// finds the old file whole or the new one whole, never neither and never a mix (POSIX
// rename(2); MoveFileEx on Windows, where another program holding `to` open, a virus
// scanner or the browser, makes it wait up to a second). Returns 0 or an errno value.
int replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace gi::platform
