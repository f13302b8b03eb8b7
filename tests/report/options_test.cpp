#include "gi/report/options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/scene/json.hpp"

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

TEST(Options, SeedsTakeTheWholeUnsignedRange) {
  Lesson l;
  ASSERT_TRUE(l.parse({"--seed", "18446744073709551615"}));
  EXPECT_EQ(l.common.seed, 18446744073709551615ull);
  ASSERT_TRUE(l.parse({"--seed", "9223372036854775808"}));  // 2^63, once refused
  EXPECT_EQ(l.common.seed, 9223372036854775808ull);
  ASSERT_TRUE(l.parse({"--seed=0"}));
  EXPECT_EQ(l.common.seed, 0u);
}

TEST(Options, ARuleBesidesTheRange) {
  int resolution = 100;
  gi::Options options("06_demo", "A demo.");
  options.add("--resolution", resolution, "hemicube resolution", 2, 2000, gi::even);
  const char* odd[] = {"06_demo", "--resolution", "33"};
  try {
    options.parse(3, odd);
    FAIL() << "an odd resolution was accepted";
  } catch (const gi::OptionError& e) {
    EXPECT_STREQ(e.what(), "--resolution must be even, got 33");
  }
  const char* even[] = {"06_demo", "--resolution=34"};
  EXPECT_TRUE(options.parse(2, even));
  EXPECT_EQ(resolution, 34);
  EXPECT_NE(options.help().find("range [2, 2000], even"), std::string::npos) << options.help();
}

TEST(Options, BadInputGivesOneClearLine) {
  EXPECT_EQ(error_of({"--width", "-5"}), "--width must be in [1, 8192], got -5");
  EXPECT_EQ(error_of({"--width", "12abc"}), "--width expects a whole number such as 64 or -3, got '12abc'");
  EXPECT_EQ(error_of({"--exposure", "nan"}), "--exposure expects a decimal number such as 2, -0.5 or 1e-3, got 'nan'");
  EXPECT_EQ(error_of({"--width"}), "--width needs a value");
  EXPECT_EQ(error_of({"--widht", "3"}), "unknown option '--widht' (did you mean --width?)");
  EXPECT_EQ(error_of({"--scene", "cornell"}), "--scene must be one of: whitted, spheres; got 'cornell'");
  EXPECT_EQ(error_of({"--seed", "-1"}), "--seed expects a whole number from 0 to 18446744073709551615, got '-1'");
  EXPECT_EQ(error_of({"--seed", "18446744073709551616"}), "--seed must be at most 18446744073709551615, got 18446744073709551616");
  EXPECT_EQ(error_of({"--seed", "+5"}), "--seed expects a whole number from 0 to 18446744073709551615, got '+5'");
  EXPECT_EQ(error_of({"--out", "--threads", "2"}), "--out needs a value, got the option '--threads'");
  EXPECT_EQ(error_of({"--out", ""}), "--out needs a value, got an empty one");
  EXPECT_EQ(error_of({"--width", "--exposure"}), "--width needs a value, got the option '--exposure'");
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

// Numbers are decimal ASCII text (number_text.hpp), whatever strtod would also take.
TEST(Options, NumbersAreDecimalAsciiOnly) {
  const std::string real = "expects a decimal number such as 2, -0.5 or 1e-3, got '";
  EXPECT_EQ(error_of({"--exposure", "0x10"}), "--exposure " + real + "0x10'");  // strtod: 16
  EXPECT_EQ(error_of({"--exposure", "inf"}), "--exposure " + real + "inf'");
  EXPECT_EQ(error_of({"--exposure", "-inf"}), "--exposure " + real + "-inf'");
  EXPECT_EQ(error_of({"--exposure", " 5"}), "--exposure " + real + " 5'");  // strtod skips the space
  EXPECT_EQ(error_of({"--exposure", "+5"}), "--exposure " + real + "+5'");
  EXPECT_EQ(error_of({"--exposure", "1e"}), "--exposure " + real + "1e'");
  EXPECT_EQ(error_of({"--exposure", "."}), "--exposure " + real + ".'");
  EXPECT_EQ(error_of({"--exposure", ""}), "--exposure " + real + "'");
  EXPECT_EQ(error_of({"--exposure", "1e999"}), "--exposure must be a finite number, got '1e999'");
  EXPECT_EQ(error_of({"--exposure", "-1e-320"}),
            "--exposure must be 0 or at least 2.2250738585072014e-308 in size (a smaller double has lost digits), "
            "got '-1e-320'");
  EXPECT_EQ(error_of({"--exposure", "1e308"}), "--exposure must be in [0, 100], got 1e308");
  const std::string whole = "expects a whole number such as 64 or -3, got '";
  EXPECT_EQ(error_of({"--width", "0x10"}), "--width " + whole + "0x10'");
  EXPECT_EQ(error_of({"--width", " 5"}), "--width " + whole + " 5'");  // strtoll skips the space
  EXPECT_EQ(error_of({"--width", "+5"}), "--width " + whole + "+5'");
  EXPECT_EQ(error_of({"--width", "5.0"}), "--width " + whole + "5.0'");
  EXPECT_EQ(error_of({"--width", "\xd9\xa3"}), "--width " + whole + "\xd9\xa3'");  // ARABIC-INDIC DIGIT THREE
  EXPECT_EQ(error_of({"--width", "99999999999999999999"}), "--width must be in [1, 8192], got 99999999999999999999");
  EXPECT_EQ(error_of({"--seed", "\xd9\xa3"}),
            "--seed expects a whole number from 0 to 18446744073709551615, got '\xd9\xa3'");
  Lesson l;
  ASSERT_TRUE(l.parse({"--exposure", "-0"}));
  EXPECT_FALSE(std::signbit(l.exposure)) << "-0 is kept as 0";
  ASSERT_TRUE(l.parse({"--exposure", ".5"}));
  EXPECT_EQ(l.exposure, 0.5);
  ASSERT_TRUE(l.parse({"--exposure", "5."}));
  EXPECT_EQ(l.exposure, 5);
  ASSERT_TRUE(l.parse({"--exposure", "2.5E+1"}));
  EXPECT_EQ(l.exposure, 25);
  EXPECT_EQ(error_of({"--width", "-0"}), "--width must be in [1, 8192], got -0");
}

TEST(Options, EachOptionOnce) {
  EXPECT_EQ(error_of({"--width", "64", "--width=4096"}), "--width is given twice; give each option once");
  EXPECT_EQ(error_of({"--fast", "--fast"}), "--fast is given twice; give each option once");
}

// A value is quoted cut short, whole characters: a message stays one line. (Control
// characters are made printable where every message leaves: printable, json_test.cpp.)
TEST(Options, QuotedValuesAreCutShort) {
  EXPECT_EQ(error_of({"--width", std::string(100, '7').c_str()}),
            "--width must be in [1, 8192], got " + std::string(40, '7') + "...");
  std::string digits;
  for (int i = 0; i < 50; ++i) digits += "\xd9\xa3";
  std::string forty;
  for (int i = 0; i < 40; ++i) forty += "\xd9\xa3";
  EXPECT_EQ(error_of({"--width", digits.c_str()}), "--width expects a whole number such as 64 or -3, got '" + forty + "...'");
}

// The browser's page builds its form from --options-json: every option, in --help's
// order, with its kind, default, range and choices, read back by a JSON reader.
TEST(Options, OptionsJsonDescribesEveryOption) {
  Lesson lesson;
  const gi::JsonValue table = gi::parse_json(lesson.options.options_json(), "options.json");
  ASSERT_EQ(table.kind, gi::JsonValue::Kind::Object);
  const gi::JsonValue* options = nullptr;
  for (const gi::JsonMember& m : table.members)
    if (m.key == "options") options = &m.value;
  ASSERT_NE(options, nullptr);
  const auto field = [](const gi::JsonValue& o, const std::string& key) -> const gi::JsonValue& {
    for (const gi::JsonMember& m : o.members)
      if (m.key == key) return m.value;
    throw std::runtime_error("no " + key);
  };
  std::vector<std::string> names, kinds;
  for (const gi::JsonValue& o : options->items) {
    names.push_back(field(o, "name").text);
    kinds.push_back(field(o, "kind").text);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"--out", "--threads", "--seed", "--width", "--exposure", "--scene",
                                             "--fast", "--depth"}));
  EXPECT_EQ(kinds, (std::vector<std::string>{"text", "integer", "unsigned", "integer", "real", "choice", "flag",
                                             "optional"}));
  const gi::JsonValue& width = options->items[3];
  EXPECT_EQ(field(width, "default").text, "640");
  EXPECT_EQ(field(width, "min").number, 1);
  EXPECT_EQ(field(width, "max").number, 8192);
  const gi::JsonValue& exposure = options->items[4];
  EXPECT_EQ(field(exposure, "max").number, 100.0);
  const gi::JsonValue& scene = options->items[5];
  ASSERT_EQ(field(scene, "choices").items.size(), 2u);
  EXPECT_EQ(field(scene, "choices").items[1].text, "spheres");
  EXPECT_EQ(field(options->items[7], "default").text, "unset");
  EXPECT_EQ(field(options->items[6], "min").kind, gi::JsonValue::Kind::Null);
}

// --options-json, like --help, prints and asks the lesson to stop before any work.
TEST(Options, OptionsJsonStopsTheRun) {
  Lesson lesson;
  testing::internal::CaptureStdout();
  const bool go_on = lesson.parse({"--width", "64", "--options-json"});
  const std::string printed = testing::internal::GetCapturedStdout();
  EXPECT_FALSE(go_on);
  EXPECT_EQ(printed, lesson.options.options_json());
  EXPECT_NE(lesson.options.help().find("--options-json"), std::string::npos);
}
