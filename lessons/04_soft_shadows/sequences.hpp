#pragma once
// Lesson 04, step 3: the numbers the shadow rays read -- independent, stratified and
// Sobol' -- and how fast each one's error in the penumbra falls (sequences.cpp).
#include "gi/accel/world.hpp"
#include "gi/image/image.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/lesson.hpp"

namespace lesson04 {

// 3. For each sequence and n = 1, 2, 4, 8, a picture with n x n random shadow rays per
//    hit (the numbers, not the pattern, spread them), its RMS error against `reference`
//    over the penumbra, and the line fitted through them on a log-log scale. The
//    penumbra is where the reference differs from the hard shadow of the light's centre
//    by more than 5%. `settings` are the lesson's, one eye ray per pixel centre.
void sequences(const gi::World& world, gi::RenderSettings settings, const gi::Image& reference, gi::Lesson& lesson);

}  // namespace lesson04
