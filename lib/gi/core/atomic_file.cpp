#include "gi/core/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "gi/core/platform/new_file.hpp"
#include "gi/core/platform/process.hpp"

namespace gi {

AtomicFile::Buffer::~Buffer() {
  if (fd_ >= 0) platform::close_file(fd_);
}

bool AtomicFile::Buffer::open(const std::filesystem::path& file) {
  fd_ = platform::open_new_file(file);
  if (fd_ < 0) error_ = errno;
  setp(data_, data_ + sizeof data_);
  return fd_ >= 0;
}

bool AtomicFile::Buffer::flush_buffer() {
  for (const char* p = pbase(); p < pptr() && error_ == 0;) {
    const long long n = platform::write_some(fd_, p, static_cast<std::size_t>(pptr() - p));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) error_ = n < 0 ? errno : EIO;
    else p += n;
  }
  setp(data_, data_ + sizeof data_);
  return error_ == 0;
}

AtomicFile::Buffer::int_type AtomicFile::Buffer::overflow(int_type c) {
  if (!flush_buffer()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) sputc(traits_type::to_char_type(c));
  return traits_type::not_eof(c);
}

int AtomicFile::Buffer::sync() { return flush_buffer() ? 0 : -1; }

bool AtomicFile::Buffer::close() {
  if (fd_ < 0) return error_ == 0;
  flush_buffer();
  // close() can report what only shows when the data leaves (network file systems).
  if (platform::close_file(fd_) != 0 && error_ == 0) error_ = errno;
  fd_ = -1;
  return error_ == 0;
}

AtomicFile::AtomicFile(std::filesystem::path file) : file_(std::move(file)) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path folder = file_.parent_path();
  std::error_code error;
  if (!folder.empty()) std::filesystem::create_directories(folder, error);
  if (error) throw WriteError("cannot create folder " + folder.string() + ": " + error.message());
  const std::string process = std::to_string(platform::current_process_id());
  temporary_ = folder / ("." + file_.filename().string() + "." + process + "." + std::to_string(counter++) + ".partial");
  if (!buffer_.open(temporary_))
    throw WriteError("cannot write " + file_.string() + ": " + std::strerror(buffer_.error()));
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  buffer_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::fail(int error) {
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
  throw WriteError("cannot write " + file_.string() + ": " + std::strerror(error));
}

std::uintmax_t AtomicFile::commit() {
  if (!buffer_.close() || !out_) fail(buffer_.error() ? buffer_.error() : EIO);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(temporary_, error);
  if (error) fail(error.value());
  if (const int failed = platform::replace_file(temporary_, file_)) fail(failed);
  committed_ = true;
  return size;
}

std::uintmax_t write_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& fill) {
  AtomicFile out(file);
  fill(out.stream());
  return out.commit();
}

bool is_partial_file(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  const std::string suffix = ".partial";
  return name.size() > suffix.size() + 1 && name[0] == '.' &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace gi
