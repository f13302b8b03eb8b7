#pragma once
#include <cstdint>

#include "gi/geometry/aabb.hpp"
#include "gi/scene/scene.hpp"

namespace gi {

// Scenes of any size, for timing ray queries as the number of primitives grows.

// `count` spheres with random centres in the cube [-5, 5]^3. The radius shrinks as
// the count grows so that the spheres fill the same fraction of the cube (5%):
// the view looks alike at every size, and only the number of primitives changes.
// A camera outside the cube looks at it; one light. Throws std::invalid_argument
// for count < 1.
Scene random_spheres(int count, std::uint64_t seed = 1);

// A furnished room, [-5, 5] x [0, 3.5] x [-5, 5], made of about `target_quads` quads:
// floor, ceiling and four walls (each face normal pointing into the room), a table, a cabinet, a sofa and
// a stack of crates (normals pointing out), every face cut into a grid of near-square
// quads of one common size. The room is closed, so every ray from inside hits
// something. The camera stands inside, by the front wall. Below about 50 (one quad
// per face) the target cannot be met. Throws std::invalid_argument for
// target_quads < 1.
Scene quad_room(int target_quads);

// The room's inside, kept 0.1 off its walls: where random rays of a benchmark start.
Aabb quad_room_interior();

}  // namespace gi
