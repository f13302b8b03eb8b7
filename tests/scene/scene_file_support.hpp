#pragma once
// Scene files for tests: written into a folder of the test's own, read back, and
// the one line of what they throw.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gi/core/platform/process.hpp"
#include "gi/scene/scene_file.hpp"

namespace gi_test {

// A folder of its own under the test's temporary directory, empty.
// ctest runs tests in parallel processes (and other build trees may be testing at the
// same time), so the folder is named by the process and the running test as well:
// two tests sharing a name such as "error" must not wipe each other's files.
inline std::filesystem::path scratch_folder(const std::string& name) {
  const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
  const std::string owner = std::to_string(gi::platform::current_process_id()) + "_" +
                            (test ? std::string(test->test_suite_name()) + "." + test->name() : "none");
  const std::filesystem::path folder = std::filesystem::path(testing::TempDir()) / "gi_scene_files" / owner / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

inline std::filesystem::path write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// What reading the scene file `text` (as box.json, beside the given other files)
// throws, or "" if it reads.
inline std::string scene_error(const std::string& text) {
  const std::filesystem::path folder = scratch_folder("error");
  write_text(folder / "box.json", text);
  try {
    (void)gi::read_scene_file(folder / "box.json");
  } catch (const gi::SceneError& e) {
    const std::string what = e.what();
    const std::string prefix = (folder / "box.json").string();
    return what.rfind(prefix, 0) == 0 ? "box.json" + what.substr(prefix.size()) : what;
  }
  return "";
}

// The top of a valid scene, to which a test adds what it checks.
inline const std::string camera = R"("camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0]})";
inline const std::string matte = R"("materials": [{"name": "white", "diffuse": 0.7}])";

}  // namespace gi_test
