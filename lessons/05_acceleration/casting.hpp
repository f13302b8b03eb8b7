#pragma once
// Lesson 05: casting a set of rays through one world on one thread, timed and counted,
// and the room's rays of every kind (casting.cpp).
#include <cstdint>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/scene/scene.hpp"

namespace lesson05 {

struct Cast {
  double seconds;                 // median of the repeats
  gi::TraversalCounts counts;     // of one pass
  std::uint64_t hits = 0;
};

// Casts every ray `repeats` times on one thread, nearest hits or any hits.
Cast cast(const gi::World& world, const std::vector<gi::Ray>& rays, bool nearest, int repeats);

// The rays of the Embree comparison (05_embree_bench, which casts 262 144 of each kind),
// so the figures compare: camera rays on a square image of about `count` pixels, as
// many from random points in random directions, and those cut to 4 m for any hits,
// like shadow rays.
struct RoomRays {
  std::vector<gi::Ray> camera, random, shadow;
};
RoomRays room_rays(const gi::Scene& room, int count, std::uint64_t seed);

}  // namespace lesson05
