#include "gi/scene/material.hpp"

#include <cmath>

namespace gi {

Color diffuse_at(const Material& material, const vec3& point) {
  if (material.checker_size <= 0) return material.diffuse;
  const double s = 1.0 / material.checker_size;
  // floor() rather than a cast: squares must not double up across x = 0 or z = 0.
  const auto i = static_cast<long long>(std::floor(point.x * s)) + static_cast<long long>(std::floor(point.z * s));
  return (i & 1) ? material.checker_diffuse : material.diffuse;
}

}  // namespace gi
