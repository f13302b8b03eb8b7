#pragma once
// Lesson 14, step 6: the numbers a path reads -- independent, stratified and Sobol' --
// and how fast each one's error falls on the Cornell box (sequences.cpp).
#include <cstdint>
#include <string>

#include "gi/report/lesson.hpp"

namespace lesson14 {

struct SequenceSettings {
  std::string reference;  // the Cornell box's converged picture, 256 x 256 (the lesson's --reference)
  int side = 64;          // the pictures: small, so that 3 x (1 + 2 + ... + 64) spp take seconds
  int max_spp = 64;       // N runs over 1, 2, 4, ... up to it
  int threads = 0;
  std::uint64_t seed = 1;
};

// 6. For each sequence and each N, a fresh picture of N spp (MIS, the default depth),
//    its relative RMS error against the reference, the line fitted through them on a
//    log-log scale, and each sequence's error per pixel at the largest N side by side.
void sequences(const SequenceSettings& s, gi::Lesson& lesson);

}  // namespace lesson14
