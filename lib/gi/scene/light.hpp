#pragma once
#include "gi/core/math.hpp"

namespace gi {

// A point light as in Whitted's model: it lights every visible point with the same
// intensity I_l, whatever the distance (no 1/r^2 falloff), so that a lecture scene
// is lit the same however large it is drawn.
struct PointLight {
  vec3 position;
  Color intensity;
};

}  // namespace gi
