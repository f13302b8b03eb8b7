#pragma once
// Lesson 12, step 4: how fine a mesh, and which method, does the Cornell box need?
// Each method's picture against the converged path-traced one (against_truth.cpp).
#include <cstdint>

#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/lesson.hpp"

namespace lesson12 {

// How much of the study to run: the meshes of up to 500 elements (Small); the rows
// that make the lesson's point in a few seconds (Lesson: a mesh refined, the direct
// light made exact, then drawn per pixel, each on two meshes); or every row of docs/12's table (Full).
enum class Study { Small, Lesson, Full };

// The against_truth table and chart, and the pictures of the truth and of the method
// nearest it: the methods `study` chooses, each solved (`threads`) and drawn through
// the box's camera at 256 x 256 (its films seeded by `seed`), scored against `truth`.
void against_truth(Study study, const gi::Truth& truth, int threads, std::uint64_t seed, gi::Lesson& lesson);

}  // namespace lesson12
