#pragma once
// Lesson 05, steps 2 to 4, benches of their own: the BVH on a room of quads and what
// each change to the tree and its walk buys there (quad_room.cpp), and every lesson's
// picture on 1, 2, ... threads (threads.cpp).
#include "gi/report/lesson.hpp"

namespace lesson05 {

// The quad_room table: a room of about `quads` quads, `rays_per_kind` rays of each kind.
void quad_room_table(int quads, int rays_per_kind, gi::Lesson& lesson);

// The changes table: builder settings and walks on the same room.
void changes_table(int quads, int rays_per_kind, gi::Lesson& lesson);

// The threads table: the pictures' sides times `scale`.
void threads_table(double scale, gi::Lesson& lesson);

}  // namespace lesson05
