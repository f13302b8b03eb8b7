// Lesson 05 -- bounding volumes and parallel computation. "Most work is spent testing
// intersections": brute force against a box per object against a bounding volume
// hierarchy, on 10 to 100 000 spheres; BVH throughput on a room of 100 000 quads, and
// what each change to the tree and its walk buys there; the render of every lesson
// so far on 1, 2, ... threads, with the same bytes; and the tree and its work as pictures.
// Step 1 is here; the benches on the room of quads and on threads are in quad_room.cpp
// and threads.cpp, the casting they share in casting.cpp, the pictures in pictures.cpp.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "casting.hpp"
#include "gi/accel/ray_sets.hpp"
#include "gi/accel/world.hpp"
#include "gi/core/timer.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "studies.hpp"

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
      const lesson05::Cast c = lesson05::cast(world, rays, true, 3);
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
    lesson05::quad_room_table(room_quads, room_rays, lesson);
    std::cout << '\n';
    lesson05::changes_table(room_quads, change_rays, lesson);
    std::cout << '\n';
    lesson05::threads_table(picture_scale, lesson);
    lesson05::pictures(std::min(max_spheres, 1000), 320, 240, lesson);
    lesson.say("\ntables, chart and pictures: " + lesson.out().string() + "/");
  });
}
