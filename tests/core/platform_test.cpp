// The calls that differ between POSIX and Windows (gi/core/platform/), held to the same
// behaviour on both: a new file's bytes exactly as written, a file replaced in one step
// (also while a reader holds it open), processes told apart by number, and a folder
// lock that makes lockers wait their turn.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

#include "gi/core/atomic_file.hpp"
#include "gi/core/platform/folder_lock.hpp"
#include "gi/core/platform/new_file.hpp"
#include "gi/core/platform/process.hpp"
#include "gi/core/platform/program.hpp"
#include "support/files.hpp"
#include "support/process.hpp"

namespace {

namespace fs = std::filesystem;
namespace platform = gi::platform;

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(testing::TempDir()) / "gi_platform_test" /
                          (std::to_string(platform::current_process_id()) + "_" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

void write_file(const fs::path& file, const std::string& bytes) {
  const int out = platform::open_new_file(file);
  ASSERT_GE(out, 0) << file << ": " << std::strerror(errno);
  for (std::size_t done = 0; done < bytes.size();) {
    const long long n = platform::write_some(out, bytes.data() + done, bytes.size() - done);
    ASSERT_GT(n, 0) << std::strerror(errno);
    done += static_cast<std::size_t>(n);
  }
  ASSERT_EQ(platform::close_file(out), 0);
}

}  // namespace

// Line ends and zero bytes go through untouched: Windows would write \n as \r\n to a
// file opened in text mode.
TEST(NewFile, KeepsEveryByte) {
  const fs::path file = scratch("bytes") / "a.bin";
  const std::string bytes = std::string("a\nb\r\nc\0d\x1a", 9) + std::string(100000, '\n');
  write_file(file, bytes);
  EXPECT_EQ(gi_test::file_text(file), bytes);
  write_file(file, "short");
  EXPECT_EQ(gi_test::file_text(file), "short") << "an existing file is emptied first";
}

TEST(NewFile, AMissingFolderIsENOENT) {
  errno = 0;
  EXPECT_EQ(platform::open_new_file(scratch("missing") / "no" / "a.bin"), -1);
  EXPECT_EQ(errno, ENOENT);
}

TEST(ReplaceFile, PutsTheNewFileInThePlaceOfTheOld) {
  const fs::path folder = scratch("replace");
  write_file(folder / "a.txt", "old");
  write_file(folder / "new.tmp", "new");
  EXPECT_EQ(platform::replace_file(folder / "new.tmp", folder / "a.txt"), 0);
  EXPECT_EQ(gi_test::file_text(folder / "a.txt"), "new");
  EXPECT_FALSE(fs::exists(folder / "new.tmp"));
  write_file(folder / "b.tmp", "b");
  EXPECT_EQ(platform::replace_file(folder / "b.tmp", folder / "b.txt"), 0) << "no old file: a plain rename";
  EXPECT_EQ(gi_test::file_text(folder / "b.txt"), "b");
  EXPECT_EQ(platform::replace_file(folder / "none.tmp", folder / "c.txt"), ENOENT);
}

// On Windows a file open for reading cannot be replaced until the reader closes it;
// replace_file waits for a reader that closes soon (here after 100 ms).
TEST(ReplaceFile, WaitsForAReaderThatHoldsTheOldFile) {
  const fs::path folder = scratch("held");
  write_file(folder / "a.txt", "old");
  write_file(folder / "new.tmp", "new");
  std::atomic<bool> open{false};
  std::thread reader([&] {
    std::ifstream in(folder / "a.txt", std::ios::binary);
    open = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  });
  while (!open) std::this_thread::yield();
  const int error = platform::replace_file(folder / "new.tmp", folder / "a.txt");
  reader.join();
  EXPECT_EQ(error, 0) << std::strerror(error);
  EXPECT_EQ(gi_test::file_text(folder / "a.txt"), "new");
}

TEST(Process, ThisProcessExistsAndNumbersNoProcessCanHaveDoNot) {
  EXPECT_GT(platform::current_process_id(), 0);
  EXPECT_TRUE(platform::process_exists(platform::current_process_id()));
  EXPECT_FALSE(platform::process_exists(-1));
  EXPECT_FALSE(platform::process_exists(999999999)) << "beyond Linux's largest (2^22) and never a Windows one";
  EXPECT_FALSE(platform::process_exists(0x7fffffffffffLL)) << "larger than any process number";
}

// A start stamp tells a process from a later one given its number: the same for as
// long as the process runs, and none once it has ended.
TEST(Process, AStartStampStaysWhileItRunsAndGoesWithIt) {
  const long long self = platform::current_process_id();
#if defined(__linux__) || defined(_WIN32)
  EXPECT_FALSE(platform::process_start_stamp(self).empty()) << "Linux has /proc, Windows GetProcessTimes";
#endif
  EXPECT_EQ(platform::process_start_stamp(self), platform::process_start_stamp(self));
  long long ended = -1;
  {
    platform::StartedProgram child(gi_test::exits_at_once());
    ended = child.id();
    EXPECT_GT(ended, 0);
    EXPECT_NE(ended, self);
    child.kill();  // waits for it
  }
  EXPECT_FALSE(platform::process_exists(ended));
  EXPECT_EQ(platform::process_start_stamp(ended), "");
  EXPECT_EQ(platform::process_start_stamp(-1), "");
  EXPECT_EQ(platform::process_start_stamp(999999999), "");
}

// The lock is held by one at a time: a second locker waits until the first lets go.
TEST(FolderLock, ASecondLockerWaitsForTheFirst) {
  const fs::path folder = scratch("lock");
  std::atomic<bool> second_has_it{false};
  std::thread second;
  {
    const platform::FolderLock first(folder);
    second = std::thread([&] {
      const platform::FolderLock lock(folder);
      second_has_it = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_FALSE(second_has_it) << "two held the lock at once";
  }
  second.join();
  EXPECT_TRUE(second_has_it);
  EXPECT_EQ(gi_test::files_in(folder).size(), 0u) << "the lock leaves nothing in the folder";
}

TEST(FolderLock, AMissingFolderIsAWriteError) {
  EXPECT_THROW(platform::FolderLock(scratch("gone") / "nowhere"), gi::WriteError);
}
