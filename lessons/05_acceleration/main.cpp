// Lesson 05 -- bounding volumes and parallel computation. "Most work is spent testing
// intersections": brute force against a box per object against a bounding volume
// hierarchy, on 10 to 100 000 spheres; BVH throughput on a room of 100 000 quads, and
// what each change to the tree and its walk buys there; and the render of every lesson
// so far on 1, 2, ... threads, with the same bytes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "gi/accel/ray_sets.hpp"
#include "gi/accel/world.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/timer.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/soft_shadow_scene.hpp"

namespace {

struct Method {
  std::string label;
  gi::Acceleration acceleration;
  gi::Split split;
};
const Method methods[] = {{"brute force", gi::Acceleration::BruteForce, gi::Split::Sah},
                          {"box per object", gi::Acceleration::BoundingBoxes, gi::Split::Sah},
                          {"BVH, median split", gi::Acceleration::Bvh, gi::Split::Median},
                          {"BVH, SAH", gi::Acceleration::Bvh, gi::Split::Sah}};

struct Cast {
  double seconds;                 // median of the repeats
  gi::TraversalCounts counts;     // of one pass
  std::uint64_t hits = 0;
};

// Casts every ray `repeats` times on one thread, nearest hits or any hits.
Cast cast(const gi::World& world, const std::vector<gi::Ray>& rays, bool nearest, int repeats) {
  Cast result{0, {}, 0};
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    gi::TraversalCounts counts;
    std::uint64_t hits = 0;
    const gi::Timer timer;
    for (const gi::Ray& ray : rays) hits += nearest ? closest_hit(world, ray, &counts).has_value() : any_hit(world, ray, &counts);
    times.push_back(timer.seconds());
    result.counts = counts;
    result.hits = hits;
  }
  result.seconds = gi::median(times);
  return result;
}

// 1. Brute force, a box per object and the BVH on ever more spheres.
void spheres_table(int max_spheres, int width, int height, gi::Lesson& lesson) {
  gi::Table table("Nearest hit of " + std::to_string(width) + "x" + std::to_string(height) +
                      " eye rays among N random spheres, 1 thread",
                  {{"N"}, {"method"}, {"build ms", 2, gi::Format::Fixed}, {"rays"}, {"nodes/ray", 1}, {"box tests/ray", 1},
                   {"sphere tests/ray", 1}, {"us/ray", 3}, {"speedup", 1}});
  std::vector<gi::Series> curves;
  for (const Method& m : methods) curves.push_back({m.label, {}, {}});
  for (int n = 10; n <= max_spheres; n *= 10) {
    gi::Scene scene = gi::random_spheres(n, lesson.seed());
    double brute_us = 0;
    for (std::size_t i = 0; i < std::size(methods); ++i) {
      const Method& m = methods[i];
      const gi::Timer build;
      const gi::World world = gi::make_world(scene, m.acceleration, {4, 12, m.split});
      const double build_ms = build.milliseconds();
      // Testing every sphere costs N per ray: cast a strided subset so that each
      // row stays under ~2e7 primitive tests.
      const bool linear = m.acceleration != gi::Acceleration::Bvh;
      const int stride = linear ? std::max(1, static_cast<int>(double(width) * height * n / 2e7)) : 1;
      const std::vector<gi::Ray> rays = gi::camera_rays(world.scene, width, height, stride);
      const Cast c = cast(world, rays, true, 3);
      const double per = 1.0 / rays.size(), us = 1e6 * c.seconds * per;
      if (i == 0) brute_us = us;
      table.add_row({n, m.label, build_ms, static_cast<long long>(rays.size()), c.counts.nodes_visited * per,
                     c.counts.box_tests * per, c.counts.primitive_tests * per, us, brute_us / us});
      curves[i].x.push_back(n);
      curves[i].y.push_back(us);
    }
  }
  lesson.table(table, "spheres");
  lesson.chart({"Time per ray against the number of spheres", "spheres N", "microseconds per eye ray", true, true,
                curves},
               "time_vs_n");
}

// The rays of the Embree comparison (05_embree_bench, which casts 262 144 of each kind),
// so the figures compare: camera rays on a square image of about `count` pixels, as
// many from random points in random directions, and those cut to 4 m for any hits,
// like shadow rays.
struct RoomRays {
  std::vector<gi::Ray> camera, random, shadow;
};
RoomRays room_rays(const gi::Scene& room, int count, std::uint64_t seed) {
  gi::Rng rng(seed);
  const int side = static_cast<int>(std::sqrt(static_cast<double>(count)));
  RoomRays rays{gi::camera_rays(room, side, side), gi::random_rays(gi::quad_room_interior(), count, rng), {}};
  rays.shadow = rays.random;
  for (gi::Ray& ray : rays.shadow) ray.t_max = 4.0;
  return rays;
}

// 2. The BVH on a room of quads, coherent and incoherent rays, one thread.
void quad_room_table(int quads, int rays_per_kind, gi::Lesson& lesson) {
  const gi::Timer build;
  const gi::World world = gi::make_world(gi::quad_room(quads));
  const double build_ms = build.milliseconds();
  const gi::BvhStats stats = gi::bvh_stats(world.bvh);
  gi::Table table("BVH (SAH) on a room of " + std::to_string(world.scene.quads.size()) + " quads, 1 thread: build " +
                      gi::format_number(build_ms, 0, gi::Format::Fixed) + " ms, " + std::to_string(stats.nodes) +
                      " nodes, depth " + std::to_string(stats.depth),
                  {{"rays"}, {"query"}, {"count"}, {"ms", 1}, {"Mrays/s", 2}, {"nodes/ray", 1}, {"quad tests/ray", 1}});
  const RoomRays rays = room_rays(world.scene, rays_per_kind, lesson.seed());
  const struct {
    const char* name;
    const std::vector<gi::Ray>& rays;
    bool nearest;
  } runs[] = {{"camera", rays.camera, true}, {"random", rays.random, true}, {"random, 4 m", rays.shadow, false}};
  for (const auto& run : runs) {
    const Cast c = cast(world, run.rays, run.nearest, 5);
    const double per = 1.0 / run.rays.size();
    table.add_row({run.name, run.nearest ? "nearest hit" : "any hit", static_cast<long long>(run.rays.size()),
                   1e3 * c.seconds, 1e-6 * run.rays.size() / c.seconds, c.counts.nodes_visited * per,
                   c.counts.primitive_tests * per});
  }
  lesson.table(table, "quad_room");
}

// 3. What each change to the tree and its walk buys, on the room of quads: the builder's
// settings (split rule, SAH bins, leaf size) under the lab's walk, then the production
// walk (bvh_fast.hpp: 8-wide nodes, float slab tests, quads beside the tree) on the same
// boxes, made wide by either collapse (bvh_collapse.hpp). Five rounds
// over all the rows, interleaved, medians reported; ratios against the lab's default.
void changes_table(int quads, int rays_per_kind, gi::Lesson& lesson) {
  struct Change {
    std::string label;
    gi::Acceleration walk;
    gi::BvhSettings settings;
  };
  std::vector<Change> changes = {
      {"lab walk, median split, leaf 4", gi::Acceleration::Bvh, {4, 12, gi::Split::Median}},
      {"lab walk, SAH 4 bins, leaf 4", gi::Acceleration::Bvh, {4, 4, gi::Split::Sah}},
      {"lab walk, SAH 12 bins, leaf 4 (default)", gi::Acceleration::Bvh, {4, 12, gi::Split::Sah}},
      {"lab walk, SAH 32 bins, leaf 4", gi::Acceleration::Bvh, {4, 32, gi::Split::Sah}},
      {"lab walk, SAH 12 bins, leaf 1", gi::Acceleration::Bvh, {1, 12, gi::Split::Sah}},
      {"lab walk, SAH 12 bins, leaf 8", gi::Acceleration::Bvh, {8, 12, gi::Split::Sah}},
      {"fast walk, median split, leaf 4", gi::Acceleration::FastBvh, {4, 12, gi::Split::Median}},
      {"fast walk, SAH 12 bins, leaf 4, largest child opened first", gi::Acceleration::FastBvh,
       {4, 12, gi::Split::Sah, gi::WideCollapse::LargestFirst}},
      {"fast walk, SAH 12 bins, leaf 4, SAH collapse (default)", gi::Acceleration::FastBvh, {4, 12, gi::Split::Sah}},
      {"fast walk, SAH 12 bins, leaf 8, SAH collapse", gi::Acceleration::FastBvh, {8, 12, gi::Split::Sah}}};
  const gi::Scene scene = gi::quad_room(quads);
  // A student kit leaves the fast walk out with exercise 5.2 (it would show the answer):
  // there, its rows are left out of the table rather than stopping the lesson.
  try {
    const gi::Scene room = gi::quad_room(1);
    gi::closest_hit(gi::make_world(room, gi::Acceleration::FastBvh, {}), gi::camera_rays(room, 1, 1)[0]);
  } catch (const gi::NotImplemented&) {
    std::erase_if(changes, [](const Change& c) { return c.walk == gi::Acceleration::FastBvh; });
    lesson.say("(the fast walk is not in this student kit: its rows are left out)");
  }
  const auto [camera, random, shadow] = room_rays(scene, rays_per_kind, lesson.seed());

  std::vector<gi::World> worlds;
  std::vector<double> build_ms;
  for (const Change& c : changes) {
    const gi::Timer build;
    worlds.push_back(gi::make_world(scene, c.walk, c.settings));
    build_ms.push_back(build.milliseconds());
  }
  // times[row][query]: one entry per round.
  std::vector<std::array<std::vector<double>, 3>> times(changes.size());
  for (int round = 0; round < 5; ++round)
    for (std::size_t i = 0; i < changes.size(); ++i) {
      times[i][0].push_back(cast(worlds[i], camera, true, 1).seconds);
      times[i][1].push_back(cast(worlds[i], random, true, 1).seconds);
      times[i][2].push_back(cast(worlds[i], shadow, false, 1).seconds);
    }
  gi::Table table("What each change buys: " + std::to_string(scene.quads.size()) + " quads, " +
                      std::to_string(camera.size()) + " camera and " + std::to_string(random.size()) +
                      " random rays, 1 thread, medians of 5 interleaved rounds; x = speed over the default",
                  {{"tree and walk"}, {"build ms", 1}, {"camera Mrays/s", 2}, {"x", 2}, {"random Mrays/s", 2}, {"x", 2},
                   {"random 4 m any hit Mrays/s", 2}, {"x", 2}});
  const std::size_t base = 2;  // the lab's default tree and walk
  for (std::size_t i = 0; i < changes.size(); ++i) {
    std::vector<gi::Cell> row{changes[i].label, build_ms[i]};
    const std::size_t counts[] = {camera.size(), random.size(), shadow.size()};
    for (int q = 0; q < 3; ++q) {
      const double t = gi::median(times[i][q]);
      row.push_back(1e-6 * counts[q] / t);
      row.push_back(gi::median(times[base][q]) / t);
    }
    table.add_row(row);
  }
  lesson.table(table, "changes");
}

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

  const int cores = lesson.threads() > 0 ? lesson.threads() : static_cast<int>(std::max(2u, std::thread::hardware_concurrency()));
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

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("05_acceleration", "Bounding volumes and threads: brute force, a box per object and a BVH "
                                       "on 10 to 100 000 spheres; a room of quads; speedup per thread.");
  int width = 160, height = 120, max_spheres = 100000, room_quads = 100000, room_rays = 65536, change_rays = 8192;
  double picture_scale = 0.5;  // 1: the lessons' own sizes (docs/05 says which figures are which)
  lesson.add_image_size(width, height, "eye-ray image (spheres table)");
  lesson.options()
      .add("--max-spheres", max_spheres, "largest sphere count (powers of 10 from 10)", 10, 1000000)
      .add("--room-quads", room_quads, "quads in the room (about)", 100, 2000000)
      .add("--room-rays", room_rays, "rays of each kind in the room table (05_embree_bench: 262144)", 16, 4000000)
      .add("--change-rays", change_rays, "rays of each kind in the table of changes", 16, 4000000)
      .add("--picture-scale", picture_scale, "scales the pictures of the threads table", 0.05, 4.0);
  return lesson.run(argc, argv, [&] {
    spheres_table(max_spheres, width, height, lesson);
    std::cout << '\n';
    quad_room_table(room_quads, room_rays, lesson);
    std::cout << '\n';
    changes_table(room_quads, change_rays, lesson);
    std::cout << '\n';
    threads_table(picture_scale, lesson);
    lesson.say("\ntables and chart: " + lesson.out().string() + "/");
  });
}
