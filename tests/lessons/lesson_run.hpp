#pragma once
// Running a lesson as a user does, and checking what it wrote.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "gi/image/image_io.hpp"

namespace gi_test {

struct LessonRun {
  int status;          // the exit status, or -1 if the lesson died of a signal
  std::string output;  // stdout and stderr together
};

// `args` go through the shell as written: quote what needs it ("--out ''").
inline LessonRun run(const std::string& lesson, const std::string& args) {
  const std::string command = std::string(GI_BIN_DIR) + "/" + lesson + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
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
