// The lessons as a user runs them: options, exit status, outputs, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gi/core/hash.hpp"
#include "lesson_run.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::bytes;
using gi_test::check_pictures;
using gi_test::LessonRun;
using gi_test::out_dir;
using gi_test::run;

// Every lesson, and the ones that render an image of a scene (which take --width,
// --height and, but for 04, --scene).
const char* const lessons[] = {"01_rays",         "02_recursive",        "03_antialiasing",
                               "04_soft_shadows", "05_acceleration",     "06_form_factors",
                               "07_hemicube",     "08_radiosity_system", "09_jacobi_gauss_seidel",
                               "10_southwell",    "11_progressive",      "12_solver_showdown",
                               "13_hierarchical",
                               "14_path_tracing", "15_radiosity_vs_path_tracing",
                               "16_two_pass"};
const char* const rendering[] = {"01_rays", "02_recursive", "03_antialiasing", "04_soft_shadows", "14_path_tracing"};
// Lessons offer --seed only if they draw random numbers, --threads only if they use threads.
const char* const without_seed[] = {"01_rays", "02_recursive", "09_jacobi_gauss_seidel", "10_southwell"};
const char* const without_threads[] = {"06_form_factors"};

template <std::size_t N>
bool among(const char* const (&list)[N], const std::string& lesson) {
  return std::find(std::begin(list), std::end(list), lesson) != std::end(list);
}
bool renders(const std::string& lesson) { return among(rendering, lesson); }

}  // namespace

TEST(Lessons, HelpExitsZeroAndListsTheCommonOptions) {
  for (const char* lesson : lessons) {
    const LessonRun r = run(lesson, "--help");
    EXPECT_EQ(r.status, 0) << lesson;
    EXPECT_NE(r.output.find("--out"), std::string::npos) << lesson << " --help does not mention --out";
    EXPECT_EQ(r.output.find("--seed") != std::string::npos, !among(without_seed, lesson)) << lesson << ": --seed";
    EXPECT_EQ(r.output.find("--threads") != std::string::npos, !among(without_threads, lesson)) << lesson << ": --threads";
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
    std::vector<std::string> bad = {"--bogus", "--out", "--out ''", "--out --threads", "--out=-x"};
    if (!among(without_threads, lesson)) bad.insert(bad.end(), {"--threads x", "--threads -2", "--threads 257"});
    if (!among(without_seed, lesson)) bad.insert(bad.end(), {"--seed 1.5", "--seed -1", "--seed 18446744073709551616"});
    if (renders(lesson)) bad.insert(bad.end(), {"--width -3", "--width", "--scene nowhere", "--height nan", "--width 15"});
    for (const std::string& args : bad) {
      const LessonRun r = run(lesson, args);
      EXPECT_EQ(r.status, 2) << lesson << " " << args;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << lesson << " " << args << ":\n" << r.output;
      EXPECT_EQ(r.output.rfind(std::string(lesson) + ": error: ", 0), 0u) << r.output;
    }
  }
  EXPECT_FALSE(fs::exists("--threads")) << "'--out --threads' made a folder named --threads";
}

TEST(Lessons, RaysWritesItsTablesAndImages) {
  const LessonRun r = run("01_rays", "--width 64 --height 48 --out " + out_dir("01"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("origin inside"), std::string::npos);
  for (const char* file : {"first_hit.png", "normals.png", "normals.pfm", "depth.png",
                           "ray_sphere.csv", "ray_plane.csv", "outputs.json"})
    EXPECT_TRUE(fs::exists(out_dir("01") + "/" + file)) << file;
  check_pictures(out_dir("01"), 1);  // the normals; the first hit and the distance are diagrams
}

TEST(Lessons, RecursiveSweepWritesImagesTablesAndChart) {
  const LessonRun r = run("02_recursive", "--width 48 --height 36 --max-depth 3 --reference-depth 6 --repeat 1 --out " +
                                        out_dir("02"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Contribution thresholds"), std::string::npos);
  for (const char* file : {"depth_0.png", "depth_3.png", "reference.png", "diff_depth_1.png", "depth_limits.csv",
                           "thresholds.csv", "rays_per_depth.csv", "error_vs_rays.svg"})
    EXPECT_TRUE(fs::exists(out_dir("02") + "/" + file)) << file;
  check_pictures(out_dir("02"), 5);
}

TEST(Lessons, AntialiasingWritesTablesCropsHeatMapAndChart) {
  const LessonRun r = run("03_antialiasing", "--width 48 --height 36 --depth 1 --reference-n 6 --out " + out_dir("03"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("jittered 4x4"), std::string::npos);
  EXPECT_NE(r.output.find("pixels split"), std::string::npos);
  for (const char* file : {"centre.png", "jittered_4x4.png", "edge_crops.png", "adaptive_samples_heatmap.png",
                           "antialiasing.csv", "adaptive.csv", "error_vs_time.svg", "reference.png"})
    EXPECT_TRUE(fs::exists(out_dir("03") + "/" + file)) << file;
  check_pictures(out_dir("03"), 6);
}

TEST(Lessons, SoftShadowsMeasuresThePenumbraAndWritesImages) {
  const LessonRun r = run("04_soft_shadows", "--width 40 --height 30 --reference-n 6 --out " + out_dir("04"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Penumbra"), std::string::npos);
  EXPECT_NE(r.output.find("centre (hard)"), std::string::npos);
  for (const char* file : {"penumbra_by_light_size.png", "hard.png", "jittered_16.png", "shadow_crops.png",
                           "reference.png", "penumbra.csv", "shadow_rays.csv", "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("04") + "/" + file)) << file;
  check_pictures(out_dir("04"), 11);
}

TEST(Lessons, FormFactorsCompareEveryMethodWithTheClosedForms) {
  const LessonRun r = run("06_form_factors", "--rays 200 --resolution 20 --order 2 --sweep-rays 1000 --reference-rays 10000 --out " +
                                              out_dir("06"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("closed form"), std::string::npos);
  EXPECT_NE(r.output.find("Where each method fails"), std::string::npos);
  for (const char* file : {"validation.csv", "failures.csv", "near_field.csv", "hemicube_aliasing.csv", "error_vs_time.svg"})
    EXPECT_TRUE(fs::exists(out_dir("06") + "/" + file)) << file;
  EXPECT_EQ(run("06_form_factors", "--resolution 33").status, 2) << "odd resolutions are refused";
}

TEST(Lessons, HemicubeWritesItsPicturesAndTables) {
  // The picture's resolution, 30, is not one of the table's (10, 20): it is drawn anyway.
  const LessonRun r = run("07_hemicube", "--elements 40 --resolution 30 --max-resolution 20 --speed-elements 100 --speed-rays 3000 --out " +
                                             out_dir("07"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("reciprocity"), std::string::npos);
  EXPECT_NE(r.output.find("sub-cell receivers"), std::string::npos);
  for (const char* file : {"item_buffer.png", "delta_form_factors.png", "form_factor_matrix.svg",
                           "object_form_factors_map.svg", "resolution.csv", "speed.csv"})
    EXPECT_TRUE(fs::exists(out_dir("07") + "/" + file)) << file;
  EXPECT_EQ(run("07_hemicube", "--resolution 21").status, 2) << "odd resolutions are refused";
}

TEST(Lessons, AccelerationTablesAndChart) {
  // Every option at its smallest; --threads bounds the threads table.
  const LessonRun r = run("05_acceleration",
                          "--width 16 --height 16 --max-spheres 10 --room-quads 100 --change-rays 16 --picture-scale 0.05 "
                          "--threads 2 "
                          "--out " + out_dir("05"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("BVH, SAH"), std::string::npos);
  EXPECT_EQ(r.output.find(" NO"), std::string::npos) << "an image differed between thread counts:\n" << r.output;
  // In a student kit the fast walk is left out with exercise 5.2, and its rows with it.
  EXPECT_TRUE(r.output.find("fast walk, SAH 12 bins, leaf 4") != std::string::npos ||
              r.output.find("the fast walk is not in this student kit") != std::string::npos)
      << r.output;
  for (const char* file : {"spheres.csv", "time_vs_n.svg", "quad_room.csv", "changes.csv", "threads.csv"})
    EXPECT_TRUE(fs::exists(out_dir("05") + "/" + file)) << file;
  std::size_t rows = 0;
  for (std::size_t at = r.output.find("05 10 000 spheres"); at != std::string::npos;
       at = r.output.find("05 10 000 spheres", at + 1))
    ++rows;
  EXPECT_EQ(rows, 2u) << "--threads 2: one row for 1 thread and one for 2\n" << r.output;
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
  for (const char* file : {"neumann_series.png", "matrix_K.png", "solution.png", "solution.pfm", "solution_flat.png",
                           "solution_flat.pfm", "neumann_0.pfm", "cornell.ply"})
    EXPECT_TRUE(fs::exists(out_dir("08") + "/" + file)) << file;
  check_pictures(out_dir("08"), 8);
  // Unclamped: the light in the PFM is far brighter than the white of the PNG (1 / 1.5).
  float brightest = 0;
  for (const gi::Pixel& p : gi::read_pfm(out_dir("08") + "/solution.pfm").pixels) brightest = std::max(brightest, p.y);
  EXPECT_GT(brightest, 2.0f) << "the PFM is clamped like the PNG";
  r = run("11_progressive", "--patches 40 --resolution 20 --width 32 --height 32 --speed-elements 200 --out " +
                                out_dir("11"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1% unshot"), std::string::npos);
  for (const char* file : {"snapshots.png", "snapshots_ambient.png", "shots_24.pfm", "shots_100_ambient.pfm",
                           "progressive.csv", "progress.svg"})
    EXPECT_TRUE(fs::exists(out_dir("11") + "/" + file)) << file;
  check_pictures(out_dir("11"), 8);
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

TEST(Lessons, HierarchicalWritesItsTablesAndRefusesBadThresholds) {
  const LessonRun r = run("13_hierarchical", "--uniform-elements 100 --min-area 1e-3 --out " +
                                                 out_dir("13"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("linear in E"), std::string::npos) << r.output;
  for (const char* file : {"thresholds.csv", "rounds.csv", "uniform.csv", "stability.csv", "relight.csv", "leaves.png",
                           "leaves.ply", "links.svg", "error_time.svg", "hierarchical.pfm", "final_gather.png"})
    EXPECT_TRUE(fs::exists(out_dir("13") + "/" + file)) << file;
  // At every threshold the final gather is nearer the truth than the same leaves' means
  // (at these leaves measured 2.70 against 4.25%, 1.67 against 2.57%, 1.37 against 1.95%).
  std::ifstream csv(out_dir("13") + "/thresholds.csv");
  std::string line, means_at;
  std::getline(csv, line);  // the header
  double means = -1;
  int compared = 0;
  while (std::getline(csv, line)) {
    const std::string eps = line.substr(0, line.find(','));
    const double error = std::stod(line.substr(line.rfind(',') + 1));  // the last column, error %
    if (line.find(",direct per pixel,") != std::string::npos) means = error, means_at = eps;
    if (line.find(",final gather,") != std::string::npos && eps == means_at) {
      EXPECT_LT(error, 0.8 * means) << "BF_eps " << eps;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3) << "a final-gather row beside each direct-per-pixel row (BF_eps 1e-2, 3e-3, 1e-3)";
  for (const char* args : {"--threshold 0", "--min-area 1", "--f-threshold nan", "--uniform-elements 10"}) {
    const LessonRun bad = run("13_hierarchical", args);
    EXPECT_EQ(bad.status, 2) << args;
    EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << args << ":\n" << bad.output;
  }
}

// How much of the mesh study to run is one choice: two of its flags together are refused
// in one line before any work.
TEST(Lessons, SolverShowdownTakesOneMeshStudy) {
  for (const char* args : {"--full --quick-mesh-study", "--skip-mesh-study --full", "--quick-mesh-study --skip-mesh-study"}) {
    const LessonRun r = run("12_solver_showdown", std::string(args) + " --out " + out_dir("12_flags"));
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out_dir("12_flags") + "/showdown.csv")) << "refused before any work: " << args;
  }
}

// The bench's one line carries an error against the path-traced truth that falls as the
// direct light moves from the mesh to the pixels (about 20% and 6% at 150 elements: a
// shadow edge crosses the coarse elements), and refuses a bad recipe in one line.
TEST(Lessons, CornellBenchScoresARecipeAgainstTheTruth) {
  const auto error_of = [](const std::string& output) {
    const std::size_t at = output.find("relative RMS ");
    return at == std::string::npos ? -1.0 : std::stod(output.substr(at + 13));
  };
  const LessonRun mesh = run("12_cornell_bench", "--elements 100 --direct exact --out " + out_dir("12_bench"));
  ASSERT_EQ(mesh.status, 0) << mesh.output;
  const LessonRun pixels =
      run("12_cornell_bench", "--elements 100 --ff monte-carlo --rays 64 --light-cells 1 --out " + out_dir("12_bench"));
  ASSERT_EQ(pixels.status, 0) << pixels.output;
  EXPECT_GT(error_of(mesh.output), 12) << mesh.output;
  EXPECT_LT(error_of(mesh.output), 30) << mesh.output;
  EXPECT_GT(error_of(pixels.output), 2) << pixels.output;
  EXPECT_LT(error_of(pixels.output), 10) << pixels.output;
  EXPECT_TRUE(fs::exists(out_dir("12_bench") + "/cornell.pfm"));
  // Lesson 13's hierarchy seated in the same bench: a coarse one (BF_eps 1e-2, min area
  // 1e-3), direct per pixel and what bounced gathered over the links, measured 2.71%
  // (5.42% from the leaves' means, before the final gather); asserted between 1.5% and 6%.
  const LessonRun tree =
      run("12_cornell_bench", "--solver hierarchical --threshold 1e-2 --min-area 1e-3 --out " + out_dir("12_bench"));
  ASSERT_EQ(tree.status, 0) << tree.output;
  EXPECT_NE(tree.output.find("hierarchical (BF_eps 1e-02, min area 1e-03, order 3)"), std::string::npos) << tree.output;
  EXPECT_GT(error_of(tree.output), 1.5) << tree.output;
  EXPECT_LT(error_of(tree.output), 6) << tree.output;
  const LessonRun bad = run("12_cornell_bench", "--direct sometimes");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
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
  // The production walk of the tree (lesson 05) gives the lab walk's picture, to the byte
  // (PNG and the linear PFM), on one thread and on two.
  for (const char* threads : {"1", "2"}) {
    const std::string out = out_dir(std::string("fast_threads") + threads);
    const LessonRun r = run("02_recursive", std::string("--scene s10 --depth 8 --width 120 --height 90 --repeat 1 "
                                                        "--accel bvh-fast --threads ") + threads + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(bytes(out + "/s10_depth_8.png"), one) << threads << " thread(s)";
    EXPECT_EQ(bytes(out + "/s10_depth_8.pfm"), bytes(out_dir("threads1") + "/s10_depth_8.pfm")) << threads;
  }
}

// Faster code must not change the picture: these are the FNV-1a hashes of the bytes
// that the plain tracer wrote before its fast paths were added (brute force four
// spheres at a time became lesson 02's default). Every way of
// finding hits, on one thread and on two, must still give them. A change that means
// to alter the picture (a new shading term) updates the hashes and says why.
TEST(Lessons, WhittedS10KeepsItsBytes) {
  const std::string png = "f6fd2a0a6f0f4ff7", pfm = "e3d19ffda9fa2948";
  for (const char* accel : {"brute-force", "bvh", "bvh-fast", "bounding-boxes"}) {
    for (const char* threads : {"1", "2"}) {
      const std::string out = out_dir(std::string("s10_bytes_") + accel + threads);
      const LessonRun r = run("02_recursive", std::string("--scene s10 --depth 8 --width 120 --height 90 --repeat 1 "
                                                          "--accel ") + accel + " --threads " + threads + " --out " + out);
      ASSERT_EQ(r.status, 0) << r.output;
      EXPECT_EQ(gi::hex(gi::fnv1a(bytes(out + "/s10_depth_8.png"))), png) << accel << ", " << threads << " thread(s)";
      EXPECT_EQ(gi::hex(gi::fnv1a(bytes(out + "/s10_depth_8.pfm"))), pfm) << accel << ", " << threads << " thread(s)";
    }
  }
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
                           "error_vs_time.svg", "plates.png", "plates_error.png", "plates.csv", "outputs.json"})
    EXPECT_TRUE(fs::exists(out_dir("14_threads1") + "/" + file)) << file;
  check_pictures(out_dir("14_threads1"), 3);
  const std::string one = bytes(out_dir("14_threads1") + "/cornell_4spp.pfm");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(bytes(out_dir("14_threads3") + "/cornell_4spp.pfm"), one);
  EXPECT_EQ(bytes(out_dir("14_threads3") + "/plates.png"), bytes(out_dir("14_threads1") + "/plates.png"));
  // Another scene renders its own reference and keeps it for the next run.
  const std::string soft = "--scene soft --width 24 --height 16 --max-spp 2 --reference-spp 16 --out " +
                           out_dir("14_soft");
  fs::remove_all(out_dir("14_soft"));
  const LessonRun first = run("14_path_tracing", soft);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("rendering a reference"), std::string::npos);
  EXPECT_EQ(run("14_path_tracing", soft).output.find("rendering a reference"), std::string::npos)
      << "the second run reads the reference the first one kept";
  EXPECT_EQ(run("14_path_tracing", "--max-spp 0").status, 2);
}

TEST(Lessons, PathTracingRefusesAMissingOrForeignReferenceBeforeAnyWork) {
  // The stored Cornell box reference is the truth every error is measured against: one
  // that is missing, or was made for another scene (a small one of the soft-shadow scene,
  // made here by 14_make_reference), stops the lesson in one line, before it writes anything.
  fs::remove_all(out_dir("14_foreign"));  // a reference left by an earlier run would be extended
  const LessonRun made = run("14_make_reference", "--scene soft --width 16 --height 16 --batch-spp 2 --out " +
                                                      out_dir("14_foreign"));
  ASSERT_EQ(made.status, 0) << made.output;
  for (const std::string& stem : {out_dir("14_nowhere") + "/cornell_256x256", out_dir("14_foreign") + "/soft_16x16"}) {
    const std::string folder = out_dir("14_refused");
    fs::remove_all(folder);
    const LessonRun r = run("14_path_tracing", "--width 32 --height 32 --max-spp 2 --reference " + stem + " --out " + folder);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("14_path_tracing: error: the stored truth of cornell cannot be used"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(folder)) << "the lesson started work before refusing its reference";
  }
}
