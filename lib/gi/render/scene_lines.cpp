#include "gi/render/scene_lines.hpp"

#include <algorithm>
#include <cmath>

namespace gi {

void draw_segment(Image& picture, const CameraFrame& frame, const vec3& a, const vec3& b, Pixel colour) {
  const auto pa = image_position(frame, a), pb = image_position(frame, b);
  // Enough dots for the segment's length in the picture; a segment that runs behind the
  // eye gets the most, its visible part being of unknown length.
  const double length = pa && pb ? glm::length(*pb - *pa) : picture.width + picture.height;
  const int dots = std::min(100000, static_cast<int>(4 * length) + 2);
  for (int k = 0; k <= dots; ++k) {
    const auto p = image_position(frame, glm::mix(a, b, static_cast<double>(k) / dots));
    if (!p) continue;
    const int x = static_cast<int>(std::floor(p->x)), y = static_cast<int>(std::floor(p->y));
    if (x >= 0 && y >= 0 && x < picture.width && y < picture.height) picture.at(x, y) = colour;
  }
}

}  // namespace gi
