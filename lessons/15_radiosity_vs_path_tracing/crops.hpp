#pragma once
// Lesson 15: a crop of each picture, side by side, enlarged (crops.cpp).
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/report/lesson.hpp"

namespace lesson15 {

// A crop of each picture, side by side, enlarged: (x, y, w) as fractions of the picture.
void crops(const std::vector<const gi::Image*>& pictures, double fx, double fy, double fw, const std::string& stem,
           const std::string& caption, gi::Lesson& lesson);

}  // namespace lesson15
