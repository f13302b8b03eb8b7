#include "gi/report/options.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

struct Lesson {
  int width = 640;
  double exposure = 1;
  std::string scene = "whitted";
  bool fast = false;
  std::optional<int> depth;
  gi::CommonOptions common;
  gi::Options options{"07_demo", "A demo."};
  Lesson() {
    gi::add_common_options(options, common, "07_demo");
    options.add("--width", width, "image width", 1, 8192)
        .add("--exposure", exposure, "exposure", 0.0, 100.0)
        .add("--scene", scene, "scene", {"whitted", "spheres"})
        .add_flag("--fast", fast, "go fast")
        .add_optional("--depth", depth, "depth", 0, 60);
  }
  bool parse(std::vector<const char*> args) {
    args.insert(args.begin(), "07_demo");
    return options.parse(static_cast<int>(args.size()), args.data());
  }
};

std::string error_of(std::vector<const char*> args) {
  try {
    Lesson().parse(std::move(args));
  } catch (const gi::OptionError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Options, DefaultsAndBothSyntaxes) {
  Lesson l;
  ASSERT_TRUE(l.parse({"--width", "800", "--exposure=2.5", "--scene", "spheres", "--fast", "--depth=3"}));
  EXPECT_EQ(l.width, 800);
  EXPECT_EQ(l.exposure, 2.5);
  EXPECT_EQ(l.scene, "spheres");
  EXPECT_TRUE(l.fast);
  EXPECT_EQ(l.depth, 3);
  EXPECT_EQ(l.common.out, "out/07_demo");
  EXPECT_EQ(l.common.threads, 0);
  Lesson untouched;
  ASSERT_TRUE(untouched.parse({}));
  EXPECT_FALSE(untouched.depth);
}

TEST(Options, RangesAreInclusive) {
  Lesson l;
  EXPECT_TRUE(l.parse({"--width", "1"}));
  EXPECT_TRUE(l.parse({"--width", "8192"}));
}

TEST(Options, BadInputGivesOneClearLine) {
  EXPECT_EQ(error_of({"--width", "-5"}), "--width must be in [1, 8192], got -5");
  EXPECT_EQ(error_of({"--width", "12abc"}), "--width expects a whole number, got '12abc'");
  EXPECT_EQ(error_of({"--exposure", "nan"}), "--exposure must be a finite number, got 'nan'");
  EXPECT_EQ(error_of({"--width"}), "--width needs a value");
  EXPECT_EQ(error_of({"--widht", "3"}), "unknown option '--widht' (did you mean --width?)");
  EXPECT_EQ(error_of({"--scene", "cornell"}), "--scene must be one of: whitted, spheres; got 'cornell'");
  EXPECT_EQ(error_of({"--seed", "-1"}), "--seed must not be negative, got -1");
  EXPECT_EQ(error_of({"--fast=1"}), "--fast takes no value");
  EXPECT_EQ(error_of({"--threads", "1000"}), "--threads must be in [0, 256], got 1000");
}

TEST(Options, HelpListsEveryOptionWithDefaultAndRange) {
  Lesson l;
  testing::internal::CaptureStdout();
  EXPECT_FALSE(l.parse({"--help"}));
  const std::string help = testing::internal::GetCapturedStdout();
  EXPECT_NE(help.find("usage: 07_demo"), std::string::npos);
  EXPECT_NE(help.find("--width VALUE"), std::string::npos);
  EXPECT_NE(help.find("(default 640), range [1, 8192]"), std::string::npos);
  EXPECT_NE(help.find("one of: whitted, spheres"), std::string::npos);
  EXPECT_NE(help.find("--out"), std::string::npos);
}
