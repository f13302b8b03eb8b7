#pragma once
// Lesson 16, step 4: where each method fails, seen beside the truth (where_each_fails.cpp).
#include <vector>

#include "gi/image/image.hpp"
#include "gi/report/lesson.hpp"
#include "pictures.hpp"

namespace lesson16 {

// Squares of every picture and of the truth, enlarged side by side (two places on each
// box, given as fractions of the picture, so they scale with --width); the whole
// pictures side by side; and the final gather's difference from the truth.
void where_each_fails(const Settings& s, const std::vector<Picture>& pictures, const gi::Image& truth,
                      gi::Lesson& lesson);

}  // namespace lesson16
