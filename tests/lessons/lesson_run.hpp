#pragma once
// Running a lesson as a user does, and reading what it wrote.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace gi_test
