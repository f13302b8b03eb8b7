#pragma once
// Lesson 15, step 3: what radiosity cannot draw, and path tracing draws slowly
// (specular.cpp).
#include "gi/report/lesson.hpp"
#include "runs.hpp"

namespace lesson15 {

// The box with a mirror ball and a glass ball, path traced at s.caustic_spp / 16, / 4
// and s.caustic_spp: the caustic_noise table, the picture and the crops of the caustic.
void specular(const Settings& s, gi::Lesson& lesson);

}  // namespace lesson15
