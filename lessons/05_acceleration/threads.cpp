// Lesson 05, step 4: every lesson's picture on 1, 2, ... threads (studies.hpp).
#include <algorithm>
#include <string>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/soft_shadow_scene.hpp"
#include "studies.hpp"

namespace lesson05 {

// 4. Every rendering lesson's picture on 1, 2, ... threads (up to --threads, or
// every core), its sides times `scale`.
void threads_table(double scale, gi::Lesson& lesson) {
  struct Job {
    std::string name;
    gi::World world;
    gi::RenderSettings settings;
  };
  std::vector<Job> jobs;
  gi::RenderSettings s;
  const auto size = [&](int w, int h) {
    s.width = std::max(8, static_cast<int>(w * scale)), s.height = std::max(8, static_cast<int>(h * scale));
  };
  const auto pixels = [&] { return " " + std::to_string(s.width) + "x" + std::to_string(s.height); };
  size(640, 480), s.trace.max_depth = 8;
  jobs.push_back({"02 whitted" + pixels() + " depth 8", gi::make_world(gi::make_scene("whitted")), s});
  size(320, 240), s.trace.max_depth = 3, s.sampling = {gi::Sampler::Jittered, 4};
  jobs.push_back({"03 aliasing" + pixels() + ", jittered 4x4", gi::make_world(gi::make_scene("aliasing")), s});
  s.sampling = {}, s.trace.max_depth = 1, s.trace.soft_shadows = {gi::LightSampling::Jittered, 4};
  jobs.push_back({"04 soft shadows, 16 rays", gi::make_world(gi::soft_shadow_scene(1.0)), s});
  s.trace.soft_shadows = {};
  jobs.push_back({"05 10 000 spheres", gi::make_world(gi::random_spheres(10000, lesson.seed())), s});

  // Every core, and at least 2 so that the table compares something; where no thread
  // can start (WebAssembly in a page) hardware_threads() is 1, and the table shows the
  // two "threads" taking turns on one.
  const int cores = lesson.threads() > 0 ? lesson.threads() : std::max(2, gi::hardware_threads());
  gi::Table table("Threads: render time (median of 5), speedup over 1 thread, efficiency (" + std::to_string(cores) +
                      " cores)",
                  {{"picture"}, {"threads"}, {"ms", 1}, {"speedup", 2}, {"efficiency %", 0}, {"same image"}});
  for (Job& job : jobs) {
    // Five rounds of 1, 2, ... threads, interleaved, so that a busy moment of the
    // (shared) machine does not fall on one thread count only; medians reported.
    std::vector<std::vector<double>> times(cores + 1);
    std::vector<gi::Image> images(cores + 1);
    for (int round = 0; round < 5; ++round)
      for (int threads = 1; threads <= cores; ++threads) {
        gi::RenderResult result = gi::render(job.world, job.settings, lesson.seed(), threads);
        times[threads].push_back(result.seconds);
        images[threads] = std::move(result.image);
      }
    const double t1 = gi::median(times[1]);
    for (int threads = 1; threads <= cores; ++threads) {
      const double t = gi::median(times[threads]);
      table.add_row({job.name, threads, 1e3 * t, t1 / t, 100 * t1 / t / threads,
                     images[threads].pixels == images[1].pixels ? "yes" : "NO"});
    }
  }
  lesson.table(table, "threads");
}

}  // namespace lesson05
