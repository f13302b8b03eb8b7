#pragma once
#include <optional>

#include "gi/scene/scene.hpp"

namespace gi {

// Brute force, as the lecture starts: test the ray against every primitive and keep
// the nearest hit. Cost O(number of primitives) per ray; the bounding volumes of
// lesson 05 bring that down.
std::optional<Hit> closest_hit(const Scene& scene, Ray ray);

// Shadow-ray query: is anything hit with t in [t_min, t_max]? Stops at the first
// hit found, which need not be the nearest.
bool any_hit(const Scene& scene, const Ray& ray);

}  // namespace gi
