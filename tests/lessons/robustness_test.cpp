// The lessons under bad conditions: a full disk, a read-only folder, a run
// killed midway, a damaged cache; solvers that stop early; sizes refused before work;
// every picture written also as PFM with its camera.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "../support/files.hpp"
#include "gi/core/atomic_file.hpp"
#include "gi/image/image_io.hpp"
#include "lesson_run.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::bytes;
using gi_test::LessonRun;
using gi_test::out_dir;
using gi_test::run;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Every PNG and PFM in `folder` reads back whole; returns how many there were.
int check_every_image(const fs::path& folder) {
  int images = 0;
  // A run killed before it made its folder (early, on a loaded machine or under the
  // sanitizers) has written nothing, half or whole.
  if (!fs::exists(folder)) return images;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const fs::path& file = entry.path();
    if (gi::is_partial_file(file)) continue;
    if (file.extension() == ".png") {
      EXPECT_NO_THROW(gi::read_png(file)) << file;
    } else if (file.extension() == ".pfm") {
      EXPECT_NO_THROW(gi::read_pfm(file)) << file;
    }
    images += file.extension() == ".png" || file.extension() == ".pfm";
  }
  return images;
}

}  // namespace

TEST(LessonFaults, AFullDiskIsExitOneWithOneLineAndNoHalfFile) {
  gi_test::SmallDisk disk(96);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  const LessonRun r = run("08_radiosity_system", "--elements 40 --resolution 20 --width 256 --height 256 --out " +
                                                     disk.path().string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("08_radiosity_system: error: cannot write"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(count(r.output, "error"), 1u) << r.output;
  for (const std::string& name : gi_test::files_in(disk.path())) EXPECT_FALSE(gi::is_partial_file(name)) << name;
  check_every_image(disk.path());
}

TEST(LessonFaults, AReadOnlyFolderIsRefusedBeforeAnyWork) {
  gi_test::SmallDisk disk(64, true);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  for (const char* lesson : {"01_rays", "09_jacobi_gauss_seidel"}) {
    const LessonRun r = run(lesson, "--out " + disk.path().string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(count(r.output, "\n"), 1u) << r.output;
    EXPECT_NE(r.output.find("Read-only file system"), std::string::npos) << r.output;
  }
}

TEST(LessonFaults, AKilledRunLeavesNoHalfFileAndTheNextRunCleansUp) {
  const std::string folder = out_dir("killed");
  fs::remove_all(folder);
  // Killed at ten moments while it writes its pictures (a whole run takes about 2 s
  // in release, far longer under the sanitizers); every file present is whole each time.
  int killed = 0;
  for (int ms : {100, 200, 300, 400, 500, 600, 700, 800, 1000, 1200}) {
    gi::platform::StartedProgram lesson(gi_test::lesson_command(
        "11_progressive", {"--patches", "60", "--resolution", "30", "--width", "400", "--height", "400",
                           "--speed-elements", "100", "--threads", "1", "--out", folder}));
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    if (!lesson.kill()) continue;  // it finished first
    ++killed;
    // What a killed run leaves is its record saying "running" (the index shows it
    // killed once the process is gone), or, killed after its last check, "complete";
    // never the page of a run that did not complete.
    const std::string record = fs::exists(folder + "/outputs.json") ? bytes(folder + "/outputs.json") : "";
    const bool complete = record.find("\"status\": \"complete\"") != std::string::npos;
    EXPECT_TRUE(record.empty() || complete || record.find("\"status\": \"running\"") != std::string::npos) << record;
    if (!complete) {
      EXPECT_FALSE(fs::exists(folder + "/index.html")) << "a killed run left a page";
    }
    check_every_image(folder);
  }
  EXPECT_GE(killed, 5) << "too few runs were killed midway for the test to mean anything";
  // The run after, small: it only has to clear the temporaries.
  const LessonRun r = run("11_progressive", "--patches 20 --resolution 10 --width 16 --height 16 --speed-elements 100 "
                                            "--out " + folder);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const std::string& name : gi_test::files_in(folder))
    EXPECT_FALSE(gi::is_partial_file(name)) << name << " from a killed run was not cleared";
  EXPECT_NE(bytes(folder + "/outputs.json").find("\"status\": \"complete\""), std::string::npos);
}

TEST(LessonFaults, ACachedReferenceIsUsedOnlyWhenWholeAndSaysSo) {
  const std::string folder = out_dir("cache03");
  fs::remove_all(folder);
  const std::string args = "--width 32 --height 24 --depth 1 --reference-n 6 --out " + folder;
  LessonRun r = run("03_antialiasing", args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("read from the cache"), std::string::npos);
  const std::string table = r.output.substr(r.output.find("Anti-aliasing, scene"));
  r = run("03_antialiasing", args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(count(r.output, "reference: read from the cache"), 1u) << r.output;
  EXPECT_EQ(r.output.substr(r.output.find("Anti-aliasing, scene")).substr(0, 60), table.substr(0, 60));
  // Truncate the cached image as a full disk would have: rendered again, not trusted.
  fs::path cached;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().filename().string().rfind("reference_", 0) == 0 && entry.path().extension() == ".pfm")
      cached = entry.path();
  ASSERT_FALSE(cached.empty());
  fs::resize_file(cached, fs::file_size(cached) / 2);
  r = run("03_antialiasing", args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("read from the cache"), std::string::npos) << "a truncated cache was trusted";
  EXPECT_NE(r.output.find("is missing or not 32x24"), std::string::npos)
      << r.output;
  // Another seed is another reference.
  r = run("03_antialiasing", args + " --seed 18446744073709551615");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("read from the cache"), std::string::npos) << "a reference of another seed was reused";
}

TEST(LessonFaults, SolversThatStopEarlyAreShownAsStopped) {
  // Gauss-Seidel reaches a residual of exactly 0 long before 1000 iterations.
  LessonRun r = run("09_jacobi_gauss_seidel", "--elements 40 --resolution 20 --iterations 1000 --out " + out_dir("09s"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Gauss-Seidel: converged after"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  r = run("09_jacobi_gauss_seidel", "--elements 40 --resolution 20 --iterations 1 --out " + out_dir("09s"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Jacobi: stopped at the limit after 1 iteration\n"), std::string::npos) << r.output;
  r = run("10_southwell", "--elements 40 --resolution 20 --sweeps 200 --out " + out_dir("10s"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Gauss-Seidel: converged after"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

TEST(LessonFaults, SizesThatCannotWorkAreRefusedBeforeAnyWork) {
  const std::string folder = out_dir("refused08");
  fs::remove_all(folder);
  const LessonRun r = run("08_radiosity_system", "--width 2000 --bounces 20 --out " + folder);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("use at most --width 1420 with --bounces 20"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(folder)) << "refused input must not make the output folder";
  EXPECT_EQ(run("08_radiosity_system", "--width 1420 --bounces 20 --help").status, 0);
}
