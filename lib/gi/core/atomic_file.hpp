#pragma once
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <functional>
#include <stdexcept>
#include <string>

namespace gi {

// A file could not be written whole: the message names the file and the reason
// ("no space left on device", "permission denied" ...).
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A file that appears whole or not at all. It is written under a temporary name in
// the same folder, ".<name>.<pid>.<n>.partial", and renamed to its real name only
// after every byte has been written and the stream closed without error; rename()
// within one folder is atomic. A run that is killed or meets a full disk leaves at
// most a hidden temporary, never a half file under the real name that a later run
// would trust.
// There is no fsync: the guarantee is against killed runs and full disks. Surviving
// a power cut would also need the file and its folder synced, at a cost per file the
// lessons do not pay.
class AtomicFile {
 public:
  // Creates the parent folders and opens the temporary; throws WriteError.
  explicit AtomicFile(std::filesystem::path file);
  ~AtomicFile();  // removes the temporary unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  // Closes, checks and renames; returns the file's size. Throws WriteError (and
  // removes the temporary) if any write failed.
  std::uintmax_t commit();

 private:
  // A buffer over a file descriptor that keeps the first error's errno: a stream
  // only says that something failed, and errno is long gone by commit().
  class Buffer : public std::streambuf {
   public:
    ~Buffer() override;
    bool open(const std::filesystem::path& file);
    bool close();  // flushes; false if any write or the close failed
    int error() const { return error_; }

   protected:
    int_type overflow(int_type c) override;
    int sync() override;

   private:
    bool flush_buffer();
    int fd_ = -1;
    int error_ = 0;
    char data_[1 << 16];
  };

  void fail(int error);
  std::filesystem::path file_, temporary_;
  Buffer buffer_;
  std::ostream out_{&buffer_};
  bool committed_ = false;
};

// What `fill` writes into the stream, as one AtomicFile. Returns the file's size.
std::uintmax_t write_atomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& fill);

// True for the temporaries AtomicFile makes (".<name>.<pid>.<n>.partial"), so that
// a later run can clear away those of a run that was killed.
bool is_partial_file(const std::filesystem::path& file);

}  // namespace gi
