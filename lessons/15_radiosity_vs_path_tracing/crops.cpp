// Lesson 15: crops side by side (crops.hpp).
#include "crops.hpp"

#include <algorithm>

#include "gi/image/diff.hpp"

namespace lesson15 {

void crops(const std::vector<const gi::Image*>& pictures, double fx, double fy, double fw, const std::string& stem,
           const std::string& caption, gi::Lesson& lesson) {
  const int size = pictures.front()->width, w = std::max(8, static_cast<int>(fw * size));
  std::vector<gi::Image> strip;
  for (const gi::Image* p : pictures)
    strip.push_back(gi::enlarge(gi::crop(*p, static_cast<int>(fx * size), static_cast<int>(fy * size), w, w),
                                std::max(1, 384 / w)));
  lesson.diagram(gi::side_by_side(strip), stem, caption, 2);
}

}  // namespace lesson15
