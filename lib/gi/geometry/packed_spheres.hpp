#pragma once
#include <optional>
#include <vector>

#include "gi/core/ray.hpp"
#include "gi/geometry/sphere.hpp"

namespace gi {

// Brute force over a handful of spheres, four at a time. Most rays miss most spheres,
// and intersect() (sphere.cpp) sends a miss away at one of two cheap early exits:
//   the sphere is behind the ray      c0 > 0 and h > 0
//   the line passes clearly outside   h^2 - a c0 < -4 eps h^2
// (a = d.d, h = d.(o - c), c0 = |o - c|^2 - r^2). Here those two tests run for four
// spheres at once, on the spheres stored coordinate by coordinate, with the same
// operations in the same order, so they give exactly the answers intersect() would.
// intersect() itself then runs only for the spheres that pass: the hits, and so the
// pictures, are the plain loop's to the last bit.
//
// The lanes are four doubles (simd::double4, gi/core/simd.hpp), and + - * < on two of
// them work lane by lane, as four scalar operations would (IEEE arithmetic rounds each
// lane as it rounds a scalar). A processor with AVX2 does the four in one instruction;
// the baseline x86-64 (SSE2) and ARM64 (NEON) in two.
struct PackedSpheres {
  static constexpr int width = 4;
  // Four spheres, coordinate by coordinate. Plain arrays, read into lanes with
  // unaligned loads: a std::vector does not promise the 32-byte alignment that the
  // lanes themselves would need.
  struct Group {
    double x[width], y[width], z[width];  // centres
    double r_squared[width];              // radius * radius, as intersect() computes it
  };
  std::vector<Group> groups;  // spheres 4k .. 4k + 3 in groups[k]
  int count = 0;              // spheres; the last group's unused lanes repeat its first sphere
};

PackedSpheres pack(const std::vector<Sphere>& spheres);

// The brute-force loops of world.cpp over spheres, with the early exits four at a
// time; `spheres` are the ones `packed` was made from. Each hit shortens the ray, as
// in the plain loop, and sets the hit's object to the sphere's index. any_sphere
// returns the index of the first sphere (in the vector's order) the ray hits, or -1.
void closest_sphere(const PackedSpheres& packed, const std::vector<Sphere>& spheres, Ray& ray,
                    std::optional<Hit>& nearest);
int any_sphere(const PackedSpheres& packed, const std::vector<Sphere>& spheres, const Ray& ray);

}  // namespace gi
