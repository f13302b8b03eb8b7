// Lesson 05: casting rays, and the room's rays (casting.hpp).
#include "casting.hpp"

#include <cmath>

#include "gi/accel/ray_sets.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/timer.hpp"
#include "gi/scene/benchmark_scenes.hpp"

namespace lesson05 {

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

RoomRays room_rays(const gi::Scene& room, int count, std::uint64_t seed) {
  gi::Rng rng(seed);
  const int side = static_cast<int>(std::sqrt(static_cast<double>(count)));
  RoomRays rays{gi::camera_rays(room, side, side), gi::random_rays(gi::quad_room_interior(), count, rng), {}};
  rays.shadow = rays.random;
  for (gi::Ray& ray : rays.shadow) ray.t_max = 4.0;
  return rays;
}

}  // namespace lesson05
