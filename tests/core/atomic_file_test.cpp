// Files appear whole or not at all: after a failed write, a full disk, a read-only
// folder and a killed process.
#include "gi/core/atomic_file.hpp"

#include <gtest/gtest.h>

#if !defined(_WIN32)
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "../support/files.hpp"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(testing::TempDir()) / "gi_atomic_test" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}


}  // namespace

TEST(AtomicFile, WritesTheWholeFileAndLeavesNoTemporary) {
  const fs::path folder = scratch("whole");
  const std::uintmax_t size =
      gi::write_atomically(folder / "sub" / "a.txt", [](std::ostream& out) { out << "hello\n"; });
  EXPECT_EQ(size, 6u);
  EXPECT_EQ(gi_test::file_text(folder / "sub" / "a.txt"), "hello\n");
  EXPECT_EQ(gi_test::files_in(folder / "sub"), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, AWriterThatFailsLeavesTheOldFileAsItWas) {
  const fs::path folder = scratch("fails");
  gi::write_atomically(folder / "a.txt", [](std::ostream& out) { out << "old"; });
  EXPECT_THROW(gi::write_atomically(folder / "a.txt",
                                    [](std::ostream& out) {
                                      out << "half of the new";
                                      throw std::runtime_error("the writer stopped");
                                    }),
               std::runtime_error);
  EXPECT_EQ(gi_test::file_text(folder / "a.txt"), "old");
  EXPECT_EQ(gi_test::files_in(folder), std::vector<std::string>{"a.txt"}) << "the temporary must be removed";
}

TEST(AtomicFile, AFullDiskIsAnErrorAndLeavesNothingBehind) {
  gi_test::SmallDisk disk(64);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  gi::write_atomically(disk.path() / "a.bin", [](std::ostream& out) { out << "old"; });
  const std::string megabyte(1 << 20, 'x');
  try {
    gi::write_atomically(disk.path() / "a.bin", [&](std::ostream& out) { out << megabyte; });
    FAIL() << "1 MB fitted on a 64 kB disk";
  } catch (const gi::WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("a.bin"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
  EXPECT_EQ(gi_test::file_text(disk.path() / "a.bin"), "old");
  EXPECT_EQ(gi_test::files_in(disk.path()), std::vector<std::string>{"a.bin"});
}

TEST(AtomicFile, AReadOnlyFolderIsAnErrorThatNamesTheFile) {
  gi_test::SmallDisk disk(64, true);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  try {
    gi::write_atomically(disk.path() / "a.txt", [](std::ostream& out) { out << "x"; });
    FAIL() << "wrote into a read-only file system";
  } catch (const gi::WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("a.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Read-only"), std::string::npos) << e.what();
  }
}

// A child process made by fork(), killed halfway through a file: POSIX only. On
// Windows LessonFaults.AKilledRunLeavesNoHalfFileAndTheNextRunCleansUp kills whole
// lessons midway instead.
#if !defined(_WIN32)
TEST(AtomicFile, AProcessKilledMidwayLeavesOnlyATemporary) {
  const fs::path folder = scratch("killed");
  gi::write_atomically(folder / "a.bin", [](std::ostream& out) { out << "old"; });
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // writes half a file and is killed before it finishes
    gi::AtomicFile file(folder / "a.bin");
    file.stream() << std::string(100000, 'x') << std::flush;
    raise(SIGKILL);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  EXPECT_EQ(gi_test::file_text(folder / "a.bin"), "old") << "a killed run must not replace the file";
  const std::vector<std::string> names = gi_test::files_in(folder);
  ASSERT_EQ(names.size(), 2u);
  for (const std::string& name : names)
    if (name != "a.bin") {
      EXPECT_TRUE(gi::is_partial_file(name)) << name;
      EXPECT_EQ(name.rfind(".a.bin." + std::to_string(child) + ".", 0), 0u) << name;
    }
}
#endif

TEST(AtomicFile, PartialFileNames) {
  EXPECT_TRUE(gi::is_partial_file(".a.png.123.0.partial"));
  EXPECT_FALSE(gi::is_partial_file("a.png"));
  EXPECT_FALSE(gi::is_partial_file("a.partial"));
  EXPECT_FALSE(gi::is_partial_file(".partial"));
}
