// The lessons as a user runs them: options, exit status, outputs, determinism.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct LessonRun {
  int status;
  std::string output;  // stdout and stderr together
};

LessonRun run(const std::string& lesson, const std::string& args) {
  const std::string command = std::string(GI_BIN_DIR) + "/" + lesson + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string out_dir(const std::string& name) { return std::string(GI_WORK_DIR) + "/out/" + name; }

std::string bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every lesson, and the ones that render an image of a scene (which take --width,
// --height and, but for 04, --scene).
const char* const lessons[] = {"01_rays",         "02_recursive",        "03_antialiasing",
                               "04_soft_shadows", "05_acceleration",     "06_form_factors",
                               "07_hemicube",     "08_radiosity_system", "09_jacobi_gauss_seidel",
                               "10_southwell",    "11_progressive",      "12_solver_showdown",
                               "14_path_tracing"};
const char* const rendering[] = {"01_rays", "02_recursive", "03_antialiasing", "04_soft_shadows", "14_path_tracing"};

bool renders(const std::string& lesson) {
  return std::find(std::begin(rendering), std::end(rendering), lesson) != std::end(rendering);
}

}  // namespace

TEST(Lessons, HelpExitsZeroAndListsTheCommonOptions) {
  for (const char* lesson : lessons) {
    const LessonRun r = run(lesson, "--help");
    EXPECT_EQ(r.status, 0) << lesson;
    for (const char* option : {"--out", "--threads", "--seed"})
      EXPECT_NE(r.output.find(option), std::string::npos) << lesson << " --help does not mention " << option;
    if (!renders(lesson)) continue;
    for (const char* option : {"--width", "--height"})
      EXPECT_NE(r.output.find(option), std::string::npos) << lesson << " --help does not mention " << option;
    if (std::string(lesson) != "04_soft_shadows") {  // its scene is made for its measurement
      EXPECT_NE(r.output.find("whitted"), std::string::npos) << lesson << " --help does not list the scenes";
    }
  }
}

TEST(Lessons, BadOptionsGiveOneLineAndStatusTwo) {
  for (const char* lesson : lessons) {
    std::vector<std::string> bad = {"--bogus", "--threads x", "--threads -2", "--out", "--seed 1.5"};
    if (renders(lesson)) bad.insert(bad.end(), {"--width -3", "--width", "--scene nowhere", "--height nan"});
    for (const std::string& args : bad) {
      const LessonRun r = run(lesson, args);
      EXPECT_EQ(r.status, 2) << lesson << " " << args;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << lesson << " " << args << ":\n" << r.output;
      EXPECT_EQ(r.output.rfind(std::string(lesson) + ": error: ", 0), 0u) << r.output;
    }
  }
}

TEST(Lessons, RaysWritesItsTablesAndImages) {
  const LessonRun r = run("01_rays", "--width 64 --height 48 --out " + out_dir("01"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("origin inside"), std::string::npos);
  for (const char* file : {"hit_or_miss.png", "normals.png", "depth.png", "ray_sphere.csv", "ray_plane.csv"})
    EXPECT_TRUE(fs::exists(out_dir("01") + "/" + file)) << file;
}

TEST(Lessons, RecursiveSweepWritesImagesTablesAndChart) {
  const LessonRun r = run("02_recursive", "--width 48 --height 36 --max-depth 3 --reference-depth 6 --repeat 1 --out " +
                                        out_dir("02"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Contribution thresholds"), std::string::npos);
  for (const char* file : {"depth_0.png", "depth_3.png", "reference.png", "diff_depth_1.png", "depth_limits.csv",
                           "thresholds.csv", "rays_per_depth.csv", "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("02") + "/" + file)) << file;
}

TEST(Lessons, AntialiasingWritesTablesCropsHeatMapAndChart) {
  const LessonRun r = run("03_antialiasing", "--width 48 --height 36 --depth 1 --reference-n 6 --out " + out_dir("03"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("jittered 4x4"), std::string::npos);
  EXPECT_NE(r.output.find("pixels split"), std::string::npos);
  for (const char* file : {"centre.png", "jittered_4x4.png", "edge_crops.png", "adaptive_samples_heatmap.png",
                           "antialiasing.csv", "adaptive.csv", "error_vs_time.svg", "reference.png"})
    EXPECT_TRUE(fs::exists(out_dir("03") + "/" + file)) << file;
}

TEST(Lessons, SoftShadowsMeasuresThePenumbraAndWritesImages) {
  const LessonRun r = run("04_soft_shadows", "--width 40 --height 30 --reference-n 6 --out " + out_dir("04"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Penumbra"), std::string::npos);
  EXPECT_NE(r.output.find("centre (hard)"), std::string::npos);
  for (const char* file : {"penumbra_by_light_size.png", "hard.png", "jittered_16.png", "shadow_crops.png",
                           "reference.png", "penumbra.csv", "shadow_rays.csv", "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("04") + "/" + file)) << file;
}

TEST(Lessons, FormFactorsCompareEveryMethodWithTheClosedForms) {
  const LessonRun r = run("06_form_factors", "--rays 200 --resolution 20 --order 2 --sweep-rays 1000 --reference-rays 10000 --out " +
                                              out_dir("06"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("closed form"), std::string::npos);
  for (const char* file : {"validation.csv", "near_field.csv", "hemicube_aliasing.csv", "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("06") + "/" + file)) << file;
  EXPECT_EQ(run("06_form_factors", "--resolution 33").status, 2) << "odd resolutions are refused";
}

TEST(Lessons, HemicubeWritesItsPicturesAndTables) {
  const LessonRun r = run("07_hemicube", "--elements 60 --resolution 20 --max-resolution 50 --speed-elements 200 --out " +
                                             out_dir("07"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("reciprocity"), std::string::npos);
  for (const char* file : {"item_buffer.png", "delta_form_factors.png", "form_factor_matrix.png", "resolution.csv",
                           "speed.csv"})
    EXPECT_TRUE(fs::exists(out_dir("07") + "/" + file)) << file;
  EXPECT_EQ(run("07_hemicube", "--resolution 21").status, 2) << "odd resolutions are refused";
}

TEST(Lessons, AccelerationTablesAndChart) {
  const LessonRun r = run("05_acceleration",
                          "--width 20 --height 16 --max-spheres 100 --room-quads 300 --picture-scale 0.1 --out " +
                              out_dir("05"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("BVH, SAH"), std::string::npos);
  EXPECT_EQ(r.output.find(" NO"), std::string::npos) << "an image differed between thread counts:\n" << r.output;
  for (const char* file : {"spheres.csv", "time_vs_n.svg", "quad_room.csv", "threads.csv"})
    EXPECT_TRUE(fs::exists(out_dir("05") + "/" + file)) << file;
}

TEST(Lessons, SolverLessonsPrintResidualTables) {
  for (const char* lesson : {"09_jacobi_gauss_seidel", "10_southwell"}) {
    const LessonRun r = run(lesson, std::string("--elements 40 --resolution 20 --out ") + out_dir(lesson));
    ASSERT_EQ(r.status, 0) << lesson << r.output;
    EXPECT_NE(r.output.find("Gauss-Seidel"), std::string::npos) << lesson;
  }
  EXPECT_TRUE(fs::exists(out_dir("09_jacobi_gauss_seidel") + "/residuals.csv"));
  EXPECT_TRUE(fs::exists(out_dir("10_southwell") + "/error_vs_work.svg"));
}

TEST(Lessons, RadiositySystemAndProgressiveRefinementDrawTheirPictures) {
  LessonRun r = run("08_radiosity_system", "--elements 60 --resolution 20 --width 32 --height 32 --out " + out_dir("08"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Neumann"), std::string::npos);
  for (const char* file : {"neumann_series.png", "matrix_K.png", "solution.png", "solution_flat.png", "cornell.ply"})
    EXPECT_TRUE(fs::exists(out_dir("08") + "/" + file)) << file;
  r = run("11_progressive", "--patches 40 --resolution 20 --width 32 --height 32 --speed-elements 200 --out " +
                                out_dir("11"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1% unshot"), std::string::npos);
  for (const char* file : {"snapshots.png", "snapshots_ambient.png", "progressive.csv", "progress.svg"})
    EXPECT_TRUE(fs::exists(out_dir("11") + "/" + file)) << file;
}

TEST(Lessons, SolverShowdownDetectsDivergence) {
  const LessonRun r = run("12_solver_showdown", "--elements 60 --bandwidth-n 200 --skip-mesh-study --out " +
                                                    out_dir("12"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("diverged"), std::string::npos) << "rho > 1 must be reported";
  EXPECT_EQ(r.output.find("nan  "), std::string::npos) << r.output;
  for (const char* file : {"showdown.csv", "error_vs_time.svg", "error_vs_work.svg", "stability.csv", "precision.csv",
                           "bandwidth.csv"})
    EXPECT_TRUE(fs::exists(out_dir("12") + "/" + file)) << file;
}

TEST(Lessons, SameBytesForAnyThreadCount) {
  for (const char* threads : {"1", "2", "5"}) {
    const LessonRun r = run("02_recursive", std::string("--scene s10 --depth 8 --width 120 --height 90 --repeat 1 --threads ") +
                                          threads + " --out " + out_dir(std::string("threads") + threads));
    ASSERT_EQ(r.status, 0) << r.output;
  }
  const std::string one = bytes(out_dir("threads1") + "/s10_depth_8.png");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(bytes(out_dir("threads2") + "/s10_depth_8.png"), one);
  EXPECT_EQ(bytes(out_dir("threads5") + "/s10_depth_8.png"), one);
}

TEST(Lessons, PathTracingWritesPicturesTablesAndChartTheSameForAnyThreadCount) {
  // 32 x 32 divides the Cornell box reference kept in the tree (256 x 256): it is read and
  // averaged down, not rendered.
  for (const char* threads : {"1", "3"}) {
    const LessonRun r = run("14_path_tracing", std::string("--width 32 --height 32 --max-spp 8 --threads ") + threads +
                                                   " --out " + out_dir(std::string("14_threads") + threads));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("convergence study"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("rendering a reference"), std::string::npos) << "the tree's reference was not used";
    EXPECT_NE(r.output.find("furnace"), std::string::npos);
  }
  for (const char* file : {"cornell_1spp.png", "cornell_1spp.pfm", "cornell_4spp.pfm", "relative_error_8spp.png",
                           "progression.png", "reference.pfm", "monte_carlo.csv", "pictures.csv", "strategies.csv",
                           "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("14_threads1") + "/" + file)) << file;
  const std::string one = bytes(out_dir("14_threads1") + "/cornell_4spp.pfm");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(bytes(out_dir("14_threads3") + "/cornell_4spp.pfm"), one);
  // Another scene renders its own reference and keeps it for the next run.
  const std::string soft = "--scene soft --width 24 --height 16 --max-spp 2 --reference-spp 16 --out " +
                           out_dir("14_soft");
  const LessonRun first = run("14_path_tracing", soft);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("rendering a reference"), std::string::npos);
  EXPECT_EQ(run("14_path_tracing", soft).output.find("rendering a reference"), std::string::npos)
      << "the second run reads the reference the first one kept";
  EXPECT_EQ(run("14_path_tracing", "--max-spp 0").status, 2);
}
