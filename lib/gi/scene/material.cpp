#include "gi/scene/material.hpp"

#include <cmath>

namespace gi {

namespace {

// floor(x) as an integer, without a call into the maths library (x86-64's baseline
// has no rounding instruction): truncate, then step down for negative non-integers.
long long floor_to_integer(double x) {
  const auto t = static_cast<long long>(x);
  return t - (x < static_cast<double>(t));
}

}  // namespace

Color diffuse_at(const Material& material, const vec3& point) {
  if (material.checker_size <= 0) return material.diffuse;
  const double s = 1.0 / material.checker_size;
  // Floor, not truncation: squares must not double up across x = 0 or z = 0.
  const long long i = floor_to_integer(point.x * s) + floor_to_integer(point.z * s);
  return (i & 1) ? material.checker_diffuse : material.diffuse;
}

}  // namespace gi
