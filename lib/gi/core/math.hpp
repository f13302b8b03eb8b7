#pragma once
// The workbench's vocabulary of vectors. Geometry and radiosity are computed in
// double precision; stored images are float (see gi/image/image.hpp).
#include <glm/glm.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace gi {

using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using Color = glm::dvec3;  // linear RGB radiance or reflectance

using glm::cross;
using glm::dot;
using glm::length;
using glm::normalize;

inline constexpr double pi = std::numbers::pi;
inline constexpr double inv_pi = 1.0 / std::numbers::pi;

inline double max_component(const vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline double luminance(const Color& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
inline double length_squared(const vec3& v) { return dot(v, v); }
inline bool is_finite(const vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace gi
