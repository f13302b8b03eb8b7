// Lesson 05, steps 2 and 3: the BVH on a room of quads (studies.hpp).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "casting.hpp"
#include "gi/accel/ray_sets.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/timer.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "studies.hpp"

namespace lesson05 {

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
  // A cast shorter than the clock's tick measures 0 s (a browser's clock ticks every
  // 0.1 ms): its rate and ratio are not known, "-", rather than infinite.
  const auto known = [](double v) { return std::isfinite(v) && v > 0 ? gi::Cell(v) : gi::Cell("-"); };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    std::vector<gi::Cell> row{changes[i].label, build_ms[i]};
    const std::size_t counts[] = {camera.size(), random.size(), shadow.size()};
    for (int q = 0; q < 3; ++q) {
      const double t = gi::median(times[i][q]), t_base = gi::median(times[base][q]);
      row.push_back(t > 0 ? known(1e-6 * counts[q] / t) : gi::Cell("-"));
      row.push_back(t > 0 ? known(t_base / t) : gi::Cell("-"));
    }
    table.add_row(row);
  }
  lesson.table(table, "changes");
}

}  // namespace lesson05
