#pragma once
#include "gi/core/math.hpp"
#include "gi/geometry/quad.hpp"

namespace gi {

// A point light as in Whitted's model: it lights every visible point with the same
// intensity I_l, whatever the distance (no 1/r^2 falloff), so that a lecture scene
// is lit the same however large it is drawn.
struct PointLight {
  vec3 position;
  Color intensity;
};

// An area light: a parallelogram of point lights. Seen from a surface point it gives
// the mean, over its area, of what a point light of intensity I at each of its points
// would give, each weighted by whether that point is visible. Partly hidden lights
// make the soft edges of shadows: the umbra sees none of the light, the penumbra part.
// Like the point light it has no falloff, and it shines to both sides.
struct QuadLight {
  Quad shape;  // shape.material is unused: the light is not a surface rays can hit
  Color intensity;
};

}  // namespace gi
