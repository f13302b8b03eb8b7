#pragma once
// Lesson 05, steps 2 to 5, benches of their own: the BVH on a room of quads and what
// each change to the tree and its walk buys there (quad_room.cpp), every lesson's
// picture on 1, 2, ... threads (threads.cpp), and the tree and its work as pictures
// (pictures.cpp).
#include "gi/report/lesson.hpp"

namespace lesson05 {

// The quad_room table: a room of about `quads` quads, `rays_per_kind` rays of each kind.
void quad_room_table(int quads, int rays_per_kind, gi::Lesson& lesson);

// The changes table: builder settings and walks on the same room.
void changes_table(int quads, int rays_per_kind, gi::Lesson& lesson);

// The threads table: the pictures' sides times `scale`.
void threads_table(double scale, gi::Lesson& lesson);

// The pictures (pictures.cpp): the BVH's boxes, level by level, over `spheres` random spheres, and
// the tests each eye ray makes, pixel by pixel, for brute force, boxes and the BVH.
void pictures(int spheres, int width, int height, gi::Lesson& lesson);

}  // namespace lesson05
