#pragma once
// Lesson 14, step 5: Veach's glossy plates, where MIS is seen to win (veach_plates.cpp).
#include <cstdint>

#include "gi/report/lesson.hpp"

namespace lesson14 {

struct PlatesSettings {
  int width = 128;             // the lesson's --width: the plates are 3/2 as wide, 4:3
  int spp = 8;                 // each strategy's samples per pixel
  int reference_spp = 256;     // MIS, for the picture each is scored against
  int threads = 0;
  std::uint64_t seed = 1;
};

// 5. The plates (gi/pathtrace/veach_plates.hpp) by BSDF sampling, light sampling and
//    MIS at the same small spp: the pictures and the reference side by side, their
//    relative errors per pixel in false colour, and the table of relative RMS.
void veach_plates(const PlatesSettings& s, gi::Lesson& lesson);

}  // namespace lesson14
