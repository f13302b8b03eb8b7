// The fixes the bad-input campaign (tests/bad_input/campaign.py) led to, each as a
// user meets it: a light 1e-300 times dimmer prints the same relative errors; a size
// the lesson could not hold is refused before any work; a scene file cannot make a
// lesson read, or quote, a file outside its folder; a huge mesh is refused at the
// lesson's limit, not after it has been read.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lesson_run.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::bytes;
using gi_test::LessonRun;
using gi_test::out_dir;
using gi_test::run;

const std::string secret = "Secret: a line no lesson may quote";

// The table's rows, each cell a number, its last column (milliseconds) left out; the
// header row is kept as text in `header`.
std::vector<std::vector<double>> numbers_without_times(const std::string& csv, std::string& header) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(csv);
  std::getline(in, header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream cells(line.substr(0, line.rfind(',')));
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

fs::path folder_of_scenes() {
  const fs::path folder = fs::path(GI_WORK_DIR) / "bad_input" / "room";
  fs::create_directories(folder);
  std::ofstream(folder.parent_path() / "secret.obj") << secret << "\n";
  std::ofstream(folder / "notes.txt") << secret << "\n";
  return folder;
}

fs::path scene_with_mesh(const fs::path& folder, const std::string& name, const std::string& mesh) {
  std::ofstream(folder / name) << R"({"camera": {"eye": [0.5, 0.5, 3], "look_at": [0.5, 0.5, 0]},
    "materials": [{"name": "lamp", "diffuse": 0.5, "emission": 1}],
    "meshes": [{"file": ")" << mesh << R"(", "material": "lamp"}]})";
  return folder / name;
}

}  // namespace

// Relative errors of a light 1e-300 times dimmer: its radiosities' squares are 0 in
// double, and the table printed NaN with status 0. Summed scaled (core/norms.hpp),
// every number is the one the unscaled light gives, to round-off.
TEST(BadInput, ADimLightPrintsTheSameRelativeErrors) {
  const std::string args = "--patches 40 --elements-per-side 1 --resolution 10 --speed-elements 100 --width 16 "
                           "--height 16 --threads 2 --out ";
  const LessonRun bright = run("11_progressive", args + out_dir("bad_input_11_bright"));
  ASSERT_EQ(bright.status, 0) << bright.output;
  const LessonRun dim = run("11_progressive", args + out_dir("bad_input_11_dim") + " --light-scale light=1e-300");
  ASSERT_EQ(dim.status, 0) << dim.output;
  EXPECT_EQ(dim.output.find("nan"), std::string::npos) << dim.output;
  // The same numbers to round-off: 1e-300 is not a power of two, so B's digits round
  // differently (1.5e-12 relative at most, measured), and a relative error taken of 0 / 0 would
  // be NaN, or a 0 where the squares underflowed.
  std::string dim_header, bright_header;
  const auto dim_rows = numbers_without_times(bytes(out_dir("bad_input_11_dim") + "/progressive.csv"), dim_header);
  const auto bright_rows = numbers_without_times(bytes(out_dir("bad_input_11_bright") + "/progressive.csv"), bright_header);
  EXPECT_EQ(dim_header, bright_header);
  ASSERT_EQ(dim_rows.size(), bright_rows.size());
  ASSERT_GT(dim_rows.size(), 5u);
  for (std::size_t r = 0; r < dim_rows.size(); ++r) {
    ASSERT_EQ(dim_rows[r].size(), bright_rows[r].size());
    for (std::size_t c = 0; c < dim_rows[r].size(); ++c)
      EXPECT_NEAR(dim_rows[r][c], bright_rows[r][c], 1e-9 * std::abs(bright_rows[r][c]))
          << "row " << r << ", column " << c;
  }
}

// 5 000 patches of 8 x 8 elements would keep 13 GB of shooting rows: refused before
// any work, from the mesher's own count.
TEST(BadInput, ASizeTheLessonCannotHoldIsRefusedAtOnce) {
  const LessonRun r = run("11_progressive", "--patches 5000 --elements-per-side 8 --out " + out_dir("bad_input_rows"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("the rows kept for shooting would take"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_dir("bad_input_rows"))) << "refused after making its folder";
  // The bench's largest mesh is capped at the matrix's limit; past it, refused at once.
  const LessonRun past = run("12_cornell_bench", "--elements 20001 --out " + out_dir("bad_input_bench"));
  EXPECT_EQ(past.status, 2) << past.output;
}

TEST(BadInput, AScenesMeshesComeFromBelowItsFolder) {
  const fs::path folder = folder_of_scenes();
  const std::string out = " --elements 20 --resolution 10 --width 16 --height 16 --bounces 1 --out ";
  for (const std::string& mesh : std::vector<std::string>{"../secret.obj", (folder.parent_path() / "secret.obj").string(),
                                                          "/etc/shadow", "notes.txt"}) {
    const LessonRun r = run("08_radiosity_system", "--scene " + scene_with_mesh(folder, "up.json", mesh).string() +
                                                       out + out_dir("bad_input_mesh"));
    EXPECT_EQ(r.status, 2) << mesh << ": " << r.output;
    EXPECT_EQ(r.output.find(secret), std::string::npos) << mesh << ": quoted a file that is not a mesh";
    EXPECT_EQ(r.output.find("root:"), std::string::npos) << mesh << ": quoted /etc/shadow";
    EXPECT_FALSE(fs::exists(out_dir("bad_input_mesh")));
  }
  // --mesh-folder allows a folder more: the same file is read, and is not OBJ text.
  const LessonRun allowed = run("08_radiosity_system", "--scene " + scene_with_mesh(folder, "up.json", "../secret.obj").string() +
                                                           " --mesh-folder " + folder.parent_path().string() + out +
                                                           out_dir("bad_input_mesh"));
  EXPECT_EQ(allowed.status, 2) << allowed.output;
  EXPECT_NE(allowed.output.find("secret.obj:1:1: the line begins with no statement this reader knows"),
            std::string::npos)
      << allowed.output;
  EXPECT_EQ(allowed.output.find(secret), std::string::npos) << "quoted the file's first line";
}

// An OBJ of 10^6 faces: refused at the lesson's 3 000 surfaces, as the faces are read.
TEST(BadInput, AHugeMeshIsRefusedAtTheLessonsLimit) {
  const fs::path folder = folder_of_scenes();
  {
    std::ofstream obj(folder / "huge.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 1'000'000; ++i) obj << "f 1 2 3\n";
  }
  const LessonRun r = run("08_radiosity_system", "--scene " + scene_with_mesh(folder, "huge.json", "huge.obj").string() +
                                                     " --out " + out_dir("bad_input_huge"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("huge.obj:3004:1: f: more than 3000 polygons"), std::string::npos) << r.output;
}
