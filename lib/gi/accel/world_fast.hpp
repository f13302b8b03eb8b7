#pragma once
#include <optional>

#include "gi/accel/world.hpp"

namespace gi {

// closest_hit and any_hit of world.hpp as the tracer's hot loop calls them
// (TraceSettings::fast_queries): the same searches, so the same answers to the bit and
// the same counts (tests/accel/world_fast_test.cpp holds them to it). Only how the ray
// is copied and where the compiler may build the searches in differ; world_fast.cpp
// says why.
std::optional<Hit> closest_hit_fast(const World& world, const Ray& ray, TraversalCounts* counts = nullptr);
bool any_hit_fast(const World& world, const Ray& ray, TraversalCounts* counts = nullptr);

}  // namespace gi
