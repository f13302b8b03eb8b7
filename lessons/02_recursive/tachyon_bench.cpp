// 02_tachyon_bench: not a lesson. Our Whitted tracer against Tachyon, John E. Stone's
// production ray tracer (Debian's tachyon-bin-nox), on s10 -- ten spheres on a
// checkered plane, two lights, a mirror and a glass ball -- at 800 x 600 and depth
// limit 8: the picture `02_recursive --scene s10 --depth 8 --fast-queries` renders (the
// tuned ray queries and local shading of accel/world_fast.cpp and raytrace/whitted_fast.cpp;
// --plain-queries for the textbook's, the same picture), whose Tachyon twin is
// lessons/scenes/s10.tachyon.dat. The two take turns, round after round (ours on
// one thread, Tachyon on one, ours on N, Tachyon on N), so that anything else the
// machine does falls on both alike. Each program's own clock of its render is read: ours
// is the render loop's (lesson 02's `ms` column), Tachyon's the "Ray Tracing Time" it
// prints; neither counts reading the scene or writing the image. Printed: medians,
// fastest and slowest of --runs renders each, the ratio of the medians, N threads
// against one, both programs' versions and the processor. Needs `tachyon` on PATH; without it, one line and status 1. Tachyon writes
// its image into a temporary folder, removed at the end. POSIX only (Linux, macOS):
// not built for Windows.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "external_program.hpp"
#include "gi/core/parallel.hpp"
#include "gi/core/platform/program.hpp"
#include "gi/core/platform/temporary_folder.hpp"
#include "gi/core/timer.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "tachyon_output.hpp"

namespace {

namespace fs = std::filesystem;

// Render times of one program at one thread count, in milliseconds.
struct Times {
  std::vector<double> ms;
  double median() const { return gi::median(ms); }
  double fastest() const { return *std::min_element(ms.begin(), ms.end()); }
  double slowest() const { return *std::max_element(ms.begin(), ms.end()); }
};

// a / b, or "-" when Tachyon's clock, which counts in steps of 0.1 ms, reads 0.
gi::Cell ratio(double a, double b) { return b > 0 ? gi::Cell(a / b) : gi::Cell("-"); }

// How to run Tachyon on the twin of s10, and what it said it was.
struct Tachyon {
  fs::path program;
  std::string scene = std::string(GI_SOURCE_DIR) + "/lessons/scenes/s10.tachyon.dat";
  fs::path image;  // in a temporary folder; each run writes over the last one's
  int width = 800, height = 600;
  double time_limit = 60;
  std::string version;  // as it prints it
};

// One Tachyon render on `threads` threads: the Ray Tracing Time it prints, in ms.
double tachyon_ms(Tachyon& tachyon, int threads) {
  const gi::platform::ProgramRun run = gi::platform::run_program(
      {tachyon.program.string(), tachyon.scene, "-res", std::to_string(tachyon.width), std::to_string(tachyon.height),
       "-numthreads", std::to_string(threads), "-format", "PPM", "-o", tachyon.image.string()},
      tachyon.time_limit);
  if (run.status != 0)
    throw std::runtime_error(tachyon.program.string() +
                             (run.status < 0 ? " was ended by a signal" : " exited with status " + std::to_string(run.status)));
  const gi::TachyonReport report = gi::parse_tachyon_output(run.output);
  tachyon.version = report.version;
  return 1e3 * report.ray_tracing_seconds;
}

// "Intel(R) Xeon(R) ...", the first "model name" of /proc/cpuinfo.
std::string processor() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("model name") && line.find(':') != std::string::npos)
      return line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
  return "an unknown processor";
}

// "g++ 12.2.0, Release build": how our side was built.
std::string build() {
#if defined(__clang__)
  std::string text = std::string("clang ") + __clang_version__;
#else
  std::string text = std::string("g++ ") + __VERSION__;
#endif
  text += std::string(", ") + GI_BUILD_TYPE + " build";
#if defined(__SANITIZE_ADDRESS__)
  text += " with AddressSanitizer (its times say nothing of the tracer's speed)";
#endif
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("02_tachyon_bench",
                    "Our Whitted tracer against Tachyon on s10, the two alternated: each one's own clock of its "
                    "render, medians and their ratio; N threads against one.",
                    {.threads = false, .seed = false});
  Tachyon tachyon;
  int runs = 5, threads = 2;
  std::string accel = "brute-force";  // lesson 02's default (docs/02_recursive.md, "Speed")
  bool plain_queries = false;
  lesson.add_image_size(tachyon.width, tachyon.height);  // both programs: Tachyon takes it as -res
  lesson.options()
      .add("--runs", runs, "renders of each program at each thread count, taking turns", 5, 1000)
      .add("--threads", threads, "the thread count set against one, for both programs", 2, 256)
      .add("--accel", accel, "how our rays find what they hit (lesson 05)", gi::acceleration_names())
      .add_flag("--plain-queries", plain_queries,
                "our ray queries and local shading by the textbook's code, not the *_fast files' (the same picture)")
      .add("--time-limit", tachyon.time_limit, "seconds a Tachyon run may take before it is stopped", 1, 3600);
  lesson.add_check([&] {
    const std::optional<fs::path> found = gi::find_on_path("tachyon");
    if (!found) throw std::runtime_error("tachyon not found on PATH: apt-get install tachyon-bin-nox");
    tachyon.program = *found;
    if (!fs::is_regular_file(tachyon.scene))
      throw std::runtime_error("Tachyon's scene " + tachyon.scene + " is missing (moved since this was built?)");
  });
  return lesson.run(argc, argv, [&] {
    const gi::platform::TemporaryFolder folder("gi_tachyon_bench_");
    tachyon.image = folder.path() / "s10.ppm";
    const gi::World world = gi::make_world(gi::make_scene("s10"), gi::acceleration_from_name(accel));
    gi::RenderSettings settings;
    settings.width = tachyon.width;
    settings.height = tachyon.height;
    settings.trace.max_depth = 8;  // RAYDEPTH 8 in the Tachyon file
    settings.trace.fast_queries = !plain_queries;

    // Round after round, each program at each thread count once.
    Times ours_one, tachyon_one, ours_many, tachyon_many;
    gi::Progress progress("rendering", 4LL * runs);
    for (int run = 0; run < runs; ++run) {
      ours_one.ms.push_back(1e3 * gi::render(world, settings, 1, 1).seconds);
      tachyon_one.ms.push_back(tachyon_ms(tachyon, 1));
      ours_many.ms.push_back(1e3 * gi::render(world, settings, 1, threads).seconds);
      tachyon_many.ms.push_back(tachyon_ms(tachyon, threads));
      progress.advance(4);
    }
    progress.finish();

    const std::string picture =
        "s10 at " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", depth limit 8";
    gi::Table times(picture + ": render times, ours and Tachyon taking turns, " + std::to_string(runs) +
                        " runs each (each program's own clock)",
                    {{"threads"}, {"ours median ms", 1}, {"ours fastest ms", 1}, {"ours slowest ms", 1},
                     {"Tachyon median ms", 1}, {"Tachyon fastest ms", 1}, {"Tachyon slowest ms", 1},
                     {"ours/Tachyon", 2, gi::Format::Fixed}});
    for (const auto& [n, ours, theirs] : {std::tuple{1, &ours_one, &tachyon_one}, std::tuple{threads, &ours_many, &tachyon_many}})
      times.add_row({n, ours->median(), ours->fastest(), ours->slowest(), theirs->median(), theirs->fastest(),
                     theirs->slowest(), ratio(ours->median(), theirs->median())});
    const std::string many = std::to_string(threads) + " threads";
    gi::Table scaling(many + " against one, the same runs (ratio of the medians)",
                      {{"program"}, {"1 thread ms", 1}, {many + " ms", 1}, {"speed-up", 2, gi::Format::Fixed}});
    scaling.add_row({"ours", ours_one.median(), ours_many.median(), ratio(ours_one.median(), ours_many.median())});
    scaling.add_row({"Tachyon", tachyon_one.median(), tachyon_many.median(),
                     ratio(tachyon_one.median(), tachyon_many.median())});

    lesson.table(times, "times");
    std::cout << '\n';
    lesson.table(scaling, "threads");
    std::cout << '\n';
    lesson.say("ours/Tachyon: our median over Tachyon's (below 1, ours is faster); speed-up: the median on one "
               "thread over the median on " + many + ".");
    lesson.say("ours: gi-workbench's Whitted tracer (lesson 02), --accel " + accel + ", ray queries and local shading by " +
               (plain_queries ? "world.cpp and whitted.cpp" : "world_fast.cpp and whitted_fast.cpp") + ", " + build() +
               ".");
    const std::string package = gi::debian_package_of(tachyon.program);
    lesson.say("Tachyon: " +
               (tachyon.version.empty() ? "it prints no version" : "\"Version " + tachyon.version + "\" as it prints it") +
               ", " + tachyon.program.string() + " (" +
               (package.empty() ? "no Debian package found for it" : "Debian package " + package) + "), " +
               fs::path(tachyon.scene).filename().string() + " at -res " + std::to_string(settings.width) + " " +
               std::to_string(settings.height) + ".");
    lesson.say("machine: " + processor() + ", " + std::to_string(gi::hardware_threads()) +
               " hardware threads.");
  });
}
