#pragma once
// Random test data for the graded tests: seeded, so every run draws the same.
#include "gi/core/math.hpp"
#include "gi/core/rng.hpp"

namespace support {

// A point (or direction) uniform in the cube [-scale, scale]^3.
inline gi::vec3 random_vector(gi::Rng& rng, double scale) {
  return scale * gi::vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
}

}  // namespace support
