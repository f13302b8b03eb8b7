#pragma once
#include "gi/raytrace/whitted.hpp"

namespace gi {

// shade_locally of whitted.hpp as trace() calls it with TraceSettings::fast_queries: the
// same operations in the same order, so the same colour to the bit and the same counts
// (tests/raytrace/whitted_fast_test.cpp); whitted_fast.cpp says what differs and why.
Color shade_locally_fast(const World& world, const Hit& hit, const vec3& n, const vec3& to_eye,
                         const TraceSettings& settings, RayCounts& counts, PixelSample& sample, int depth);

}  // namespace gi
