#include "gi/accel/world_fast.hpp"

namespace gi {

namespace {

// A copy of the ray, read one double at a time. The caller has just written the ray
// double by double, and a plain copy reads it 16 bytes at a time: the processor
// cannot hand a 16-byte read the data of two 8-byte writes still on their way to the
// cache, so the read waits until they get there, and the work behind it with it
// (a "store-forwarding stall"; perf put 10% of the s10 render on it). `volatile`
// keeps the compiler from merging the reads.
Ray copy_double_by_double(const Ray& ray) {
  const volatile Ray& from = ray;
  return Ray{vec3(from.origin.x, from.origin.y, from.origin.z),
             vec3(from.direction.x, from.direction.y, from.direction.z), from.t_min, from.t_max};
}

}  // namespace

// Neither is built into its caller: inside the recursive trace() the three
// accelerations' loops made a stack frame so large that the whole tracer ran 5% slower.
[[gnu::noinline]] std::optional<Hit> closest_hit_fast(const World& world, const Ray& query, TraversalCounts* counts) {
  Ray ray = copy_double_by_double(query);  // each hit shortens this copy
  return closest_hit_in_place(world, ray, counts);
}

[[gnu::noinline]] bool any_hit_fast(const World& world, const Ray& ray, TraversalCounts* counts) {
  return any_hit(world, ray, counts);
}

}  // namespace gi
