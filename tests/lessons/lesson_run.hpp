#pragma once
// Running a lesson as a user does, and checking what it wrote.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gi/core/platform/program.hpp"
#include "gi/image/image_io.hpp"
#include "support/process.hpp"

namespace gi_test {

struct LessonRun {
  int status;          // the exit status, -1 if the lesson was killed, 127 if it could not start
  std::string output;  // stdout and stderr together
};

// The lesson and its arguments, as the build runs its programs.
inline std::vector<std::string> lesson_command(const std::string& lesson, const std::vector<std::string>& args) {
  std::vector<std::string> command{std::string(GI_BIN_DIR) + "/" + lesson};
  command.insert(command.end(), args.begin(), args.end());
  return emulated(command);
}

// `args` are split into words as a shell would: quote what needs it ("--out ''").
// An hour at most: far beyond any lesson the tests run, even emulated.
inline LessonRun run(const std::string& lesson, const std::string& args) {
  try {
    const gi::platform::ProgramRun r = gi::platform::run_program(lesson_command(lesson, shell_words(args)), 3600);
    return {r.status, r.output};
  } catch (const std::runtime_error& e) {
    return {127, e.what()};
  }
}

inline std::string out_dir(const std::string& name) { return std::string(GI_WORK_DIR) + "/out/" + name; }

inline std::string bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every picture in outputs.json has its PFM, of the PNG's size, and a stated camera;
// there are `expected` of them, and the run completed.
inline void check_pictures(const std::filesystem::path& folder, std::size_t expected) {
  const std::string json = bytes(folder / "outputs.json");
  ASSERT_NE(json.find("\"status\": \"complete\""), std::string::npos) << json;
  std::size_t pictures = 0;
  for (std::size_t at = json.find("\"kind\": \"picture\""); at != std::string::npos;
       at = json.find("\"kind\": \"picture\"", at + 1), ++pictures) {
    const std::size_t file = json.find("\"file\": \"", at) + 9, linear = json.find("\"linear\": \"", at) + 11;
    const std::filesystem::path png = folder / json.substr(file, json.find('"', file) - file);
    const std::filesystem::path pfm = folder / json.substr(linear, json.find('"', linear) - linear);
    EXPECT_EQ(pfm.extension(), ".pfm");
    EXPECT_TRUE(gi::read_pfm(pfm).same_size(gi::read_png(png))) << pfm;
    EXPECT_LT(json.find("\"view\": {\"eye\": [", at), json.find("}}", at)) << "no camera for " << png;
  }
  EXPECT_EQ(pictures, expected) << json;
}

}  // namespace gi_test
