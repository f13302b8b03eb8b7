// The lesson object: exit status by kind of failure, the whole configuration checked
// before any work, every output recorded in order and in place at the end.
#include "gi/report/lesson.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "../support/files.hpp"
#include "gi/core/atomic_file.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/platform/process.hpp"
#include "gi/image/image_io.hpp"
#include "gi/report/options.hpp"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(testing::TempDir()) / "gi_lesson_test" / name;
  fs::remove_all(folder);
  return folder;
}


struct LessonRun {
  int status;
  std::string out, err;
};

// Runs a lesson "01_x" with the arguments and the body, capturing stdout and stderr.
LessonRun run(std::vector<std::string> args, const std::function<void(gi::Lesson&)>& body,
        const std::function<void(gi::Lesson&)>& setup = {}) {
  gi::Lesson lesson("01_x", "A test lesson.");
  int width = 32, height = 16;
  lesson.add_image_size(width, height);
  if (setup) setup(lesson);
  args.insert(args.begin(), "01_x");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = lesson.run(static_cast<int>(argv.size()), argv.data(), [&] { body(lesson); });
  const std::string out = testing::internal::GetCapturedStdout();
  return {status, out, testing::internal::GetCapturedStderr()};
}

gi::View view(int width, int height) {
  gi::View v;
  v.camera.eye = {0, 1, 5};
  v.width = width;
  v.height = height;
  v.pixel_samples = "one eye ray through the pixel centre";
  return v;
}

}  // namespace

TEST(RunLesson, ExitStatusAndOneLineOnStderr) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(gi::run_lesson("01_x", [] { return 0; }), 0);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw gi::OptionError("--width must be in [1, 10], got 0"); }), 2);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw gi::NotImplemented("exercise 1.1 ray-sphere"); }), 3);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw std::invalid_argument("sphere: bad radius"); }), 1);
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "01_x: error: --width must be in [1, 10], got 0 (try --help)\n"
            "01_x: exercise 1.1 ray-sphere is not implemented yet (see exercises/)\n"
            "01_x: error: sphere: bad radius\n");
}

TEST(Lesson, RecordsEveryOutputInOrderAndWritesPfmBesideEachPicture) {
  const fs::path out = scratch("record");
  const LessonRun r = run({"--out", out.string(), "--width", "20"}, [](gi::Lesson& lesson) {
    lesson.say("a line of text");
    gi::Table table("Squares", {{"n"}, {"n^2"}});
    table.add_row({3, 9});
    lesson.table(table, "squares");
    gi::Image radiance(20, 16, gi::Pixel(4.0f, 0.5f, 0.25f));  // brighter than white: the PNG clamps, the PFM must not
    lesson.picture(radiance, "render", "a flat picture", view(20, 16), 0.5);
    lesson.diagram(gi::Image(4, 4), "heat", "a heat map");
    lesson.chart({"A chart", "x", "y", false, false, {{"s", {1, 2}, {3, 4}}}}, "chart");
  });
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.rfind("a line of text\nSquares\n", 0), 0u) << r.out;
  for (const char* file : {"squares.csv", "render.png", "render.pfm", "heat.png", "chart.svg", "outputs.json"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const std::string json = gi_test::file_text(out / "outputs.json");
  const std::vector<std::string> in_order = {"\"status\": \"complete\"",  "\"kind\": \"text\"",
                                             "\"kind\": \"table\"",       "\"file\": \"squares.csv\"",
                                             "\"kind\": \"picture\"",     "\"linear\": \"render.pfm\"",
                                             "\"exposure\": 0.5",         "\"eye\": [0, 1, 5]",
                                             "\"width\": 20",             "\"kind\": \"diagram\"",
                                             "\"kind\": \"chart\""};
  std::size_t at = 0;
  for (const std::string& s : in_order) {
    const std::size_t found = json.find(s, at);
    EXPECT_NE(found, std::string::npos) << s << " missing or out of order in\n" << json;
    if (found != std::string::npos) at = found;
  }
  EXPECT_NE(json.find("\"--width\", \"20\""), std::string::npos) << "the command line is recorded";
  EXPECT_EQ(gi::read_pfm(out / "render.pfm").at(3, 2), gi::Pixel(4.0f, 0.5f, 0.25f)) << "the linear file is not clamped";
  EXPECT_EQ(gi::read_png(out / "render.png").at(3, 2).x, 1.0f) << "the PNG shows clamp(0.5 * 4)";
}

TEST(Lesson, BadConfigurationIsExitTwoBeforeAnyWork) {
  const fs::path out = scratch("bad");
  std::ofstream(fs::path(testing::TempDir()) / "gi_lesson_test" / "a_file") << "x";
  bool worked = false;
  const auto body = [&](gi::Lesson&) { worked = true; };
  const std::string file = (fs::path(testing::TempDir()) / "gi_lesson_test" / "a_file").string();
  const struct {
    std::vector<std::string> args;
    const char* message;
  } cases[] = {
      {{"--out", ""}, "--out needs a value, got an empty one"},
      {{"--out", "--threads"}, "--out needs a value, got the option '--threads'"},
      {{"--out=--threads"}, "--out must name a folder, got '--threads'"},
      {{"--out", file}, "is a file, not a folder"},
      {{"--out", file + "/below"}, "cannot create the folder"},
      {{"--width", "15"}, "--width must be in [16, 4096], got 15"},
      {{"--height", "4097"}, "--height must be in [16, 4096], got 4097"},
      {{"--seed", "-1"}, "--seed expects a whole number"},
  };
  for (const auto& c : cases) {
    const LessonRun r = run(c.args, body);
    EXPECT_EQ(r.status, 2) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // A check of the combination runs before the folder is made.
  const LessonRun r = run({"--out", out.string()}, body, [](gi::Lesson& lesson) {
    lesson.add_check([] { throw gi::OptionError("--width times --bounces is too wide"); });
  });
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "01_x: error: --width times --bounces is too wide (try --help)\n");
  EXPECT_FALSE(worked);
  EXPECT_FALSE(fs::exists(out)) << "refused input must leave nothing behind";
}

TEST(Lesson, ExitOneForFailuresWhileRunningAndThreeForExercises) {
  const fs::path out = scratch("fail");
  LessonRun r = run({"--out", out.string()}, [](gi::Lesson&) { throw std::runtime_error("the solver diverged"); });
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "01_x: error: the solver diverged\n");
  EXPECT_NE(gi_test::file_text(out / "outputs.json").find("\"status\": \"failed: the solver diverged\""), std::string::npos);
  r = run({"--out", out.string()}, [](gi::Lesson&) { throw gi::NotImplemented("exercise 5.2 BVH traversal"); });
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("--accel brute-force"), std::string::npos) << r.err;
  r = run({"--help"}, [](gi::Lesson&) { FAIL() << "--help must not run the lesson"; });
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--width VALUE"), std::string::npos);
}

TEST(Lesson, AFileThatVanishedBeforeTheEndIsAFailure) {
  const fs::path out = scratch("vanished");
  const LessonRun r = run({"--out", out.string()}, [&](gi::Lesson& lesson) {
    lesson.diagram(gi::Image(4, 4), "heat", "a heat map");
    fs::remove(out / "heat.png");
  });
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("heat.png is missing"), std::string::npos) << r.err;
}

// While it runs, the record says "running" and names this process: a run killed now
// leaves that, never the older run's "complete", nor its page.
TEST(Lesson, ARunThatIsKilledLeavesARunningRecordAndItsTemporariesAreCleared) {
  const fs::path out = scratch("killed");
  fs::create_directories(out);
  std::ofstream(out / "outputs.json") << "{\"status\": \"complete\"}";  // an older run's record
  std::ofstream(out / "index.html") << "an older run's page";
  std::ofstream(out / ".a.png.999999999.0.partial") << "half";          // a dead process's temporary
  const std::string alive = ".b.png." + std::to_string(gi::platform::current_process_id()) + ".0.partial";
  std::ofstream(out / alive) << "being written";
  const LessonRun r = run({"--out", out.string()}, [&](gi::Lesson&) {
    const std::string record = gi_test::file_text(out / "outputs.json");
    EXPECT_NE(record.find("\"status\": \"running\""), std::string::npos) << record;
    EXPECT_NE(record.find("\"process\": {\"id\": " + std::to_string(gi::platform::current_process_id()) + ", \"started\": \""),
              std::string::npos) << record;
    EXPECT_FALSE(fs::exists(out / "index.html")) << "a run killed now must not leave the old page";
  });
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / ".a.png.999999999.0.partial"));
  EXPECT_TRUE(fs::exists(out / alive)) << "a live process's temporary is not ours to remove";
}

TEST(Lesson, AReadOnlyFolderIsRefusedBeforeAnyWork) {
  gi_test::SmallDisk disk(64, true);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  const LessonRun r = run({"--out", disk.path().string()}, [](gi::Lesson&) { FAIL() << "ran into a read-only folder"; });
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot write into"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Read-only file system"), std::string::npos) << r.err;
}

TEST(Lesson, AFullDiskIsExitOneAndLeavesNoHalfFile) {
  gi_test::SmallDisk disk(64);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  const LessonRun r = run({"--out", disk.path().string(), "--width", "512", "--height", "512"}, [](gi::Lesson& lesson) {
    lesson.say("before");
    // 512 x 512 x 12 bytes of PFM do not fit in 64 kB.
    lesson.picture(gi::Image(512, 512, gi::Pixel(0.5f)), "big", "too big", view(512, 512));
  });
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const std::string& name : gi_test::files_in(disk.path()))
    EXPECT_TRUE(name == "big.png" || name == "outputs.json" || name == "index.html") << "left behind: " << name;
  // The record and its page, when they fit, say the run failed.
  for (const char* name : {"outputs.json", "index.html"})
    if (fs::exists(disk.path() / name)) {
      EXPECT_NE(gi_test::file_text(disk.path() / name).find("failed"), std::string::npos) << name;
    }
}

TEST(Lesson, WritesItsReportPageAndTheIndexOfLessonsAboveAFolderNamedAfterIt) {
  const fs::path root = scratch("pages");
  const LessonRun r = run({"--out", (root / "01_x").string()}, [](gi::Lesson& lesson) {
    lesson.say("a line of text");
    lesson.picture(gi::Image(32, 16, gi::Pixel(0.5f)), "grey", "a grey picture", view(32, 16));
  });
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = gi_test::file_text(root / "01_x" / "index.html");
  EXPECT_LT(page.find("<pre>a line of text"), page.find("<img src=\"grey.png\"")) << page;
  EXPECT_NE(page.find("<p class=\"status complete\">complete</p>"), std::string::npos) << page;
  EXPECT_NE(gi_test::file_text(root / "index.html").find("<a href=\"01_x/index.html\">01_x</a>"), std::string::npos);

  // A folder under another name may sit anywhere: its page, and no index beside it.
  const fs::path other = scratch("pages_elsewhere");
  ASSERT_EQ(run({"--out", (other / "mine").string()}, [](gi::Lesson& lesson) { lesson.say("x"); }).status, 0);
  EXPECT_TRUE(fs::exists(other / "mine" / "index.html"));
  EXPECT_FALSE(fs::exists(other / "index.html"));
}
