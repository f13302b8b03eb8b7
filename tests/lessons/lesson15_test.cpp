// Lesson 15 as a user runs it: its outputs, the same bytes for any thread count, and
// the command lines and references it refuses before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "lesson_run.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::bytes;
using gi_test::check_pictures;
using gi_test::LessonRun;
using gi_test::out_dir;
using gi_test::run;

const char* const lesson = "15_radiosity_vs_path_tracing";

TEST(Lesson15, WritesEveryPictureAndTheSameBytesForAnyThreadCount) {
  for (const char* threads : {"1", "3"}) {
    const LessonRun r = run(lesson, std::string("--size 64 --max-spp 4 --caustic-spp 32 --threads ") + threads +
                                        " --out " + out_dir(std::string("15_threads") + threads));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("path tracing's error law"), std::string::npos) << r.output;
  }
  const std::string folder = out_dir("15_threads1");
  for (const char* file : {"every_method.csv", "error_vs_time.svg", "caustic_noise.csv", "crop_short_block.png",
                           "crop_ceiling.png", "crop_tall_block.png", "crop_caustic.png", "truth.pfm", "outputs.json"})
    EXPECT_TRUE(fs::exists(folder + "/" + file)) << file;
  // The coarse and best radiosity pictures, path tracing at about the best's time, the
  // truth, and the mirror-and-glass box: each as PNG and PFM, with its camera.
  check_pictures(folder, 5);
  for (const char* file : {"radiosity_coarse.pfm", "radiosity_best.pfm", "mirror_and_glass.pfm"}) {
    const std::string one = bytes(folder + "/" + file);
    ASSERT_FALSE(one.empty()) << file;
    EXPECT_EQ(bytes(out_dir("15_threads3") + "/" + file), one) << file;
  }
}

TEST(Lesson15, RefusesABadSizeTheReferencesOwnSeedAndAMissingReference) {
  const std::string folder = out_dir("15_refused");
  const auto refused = [&](const std::string& args, int status, const std::string& message) {
    fs::remove_all(folder);
    const LessonRun r = run(lesson, args + " --out " + folder);
    EXPECT_EQ(r.status, status) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(folder)) << args << ": the lesson started work before refusing";
  };
  refused("--size 100", 2, "--size must divide 256");
  refused("--size 32", 2, "--size");
  // The stored reference drew from seeds 1000000 ... 1000010: a picture from one of them
  // at its own size would repeat the truth's samples and score too well.
  refused("--size 256 --seed 1000003", 2, "one of the reference's own seeds");
  refused("--reference " + out_dir("15_nowhere") + "/cornell_256x256", 1,
          "15_radiosity_vs_path_tracing: error: the stored truth of cornell cannot be used");
}

}  // namespace
