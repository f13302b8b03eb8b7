#pragma once
// Lesson 14, step 6: the numbers a path reads -- independent, stratified and Sobol' --
// and how fast each one's error falls on the Cornell box (sequences.cpp).
#include <cstdint>

#include "gi/render/truth.hpp"
#include "gi/report/lesson.hpp"

namespace lesson14 {

// Small pictures, so that 3 x (1 + 2 + ... + 64) spp take seconds: at most 64 x 64 and
// 64 spp, less when the lesson's own pictures are smaller.
struct SequenceSettings {
  int side = 64;     // a power of two that divides the stored reference's 256
  int max_spp = 64;  // N runs over 1, 2, 4, ... up to it (2 at least: a slope needs two points)
  int threads = 0;
  std::uint64_t seed = 1;
};
// The step's settings for pictures of width x height and up to max_spp samples per pixel.
SequenceSettings sequence_settings(int width, int height, int max_spp);

// 6. For each sequence and each N, a fresh picture of the Cornell box at N spp (MIS,
//    the default depth), its error against `reference` (the stored converged box,
//    side x side), the line fitted through them on a log-log scale, and each sequence's
//    error per pixel at the largest N side by side.
void sequences(const SequenceSettings& s, const gi::Truth& reference, gi::Lesson& lesson);

}  // namespace lesson14
