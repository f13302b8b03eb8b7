#include "gi/geometry/packed_spheres.hpp"

#include <cstring>
#include <limits>

#include "gi/core/simd.hpp"

namespace gi {

namespace {

using Lanes = simd::double4;
constexpr int width = PackedSpheres::width;

// The ray's numbers in every lane, once per ray rather than once per group.
struct LanesRay {
  Lanes ox, oy, oz, dx, dy, dz;
  Lanes a;  // d.d
};

[[gnu::always_inline]] inline LanesRay spread(const Ray& ray) {
  const vec3& o = ray.origin;
  const vec3& d = ray.direction;
  const double a = dot(d, d);
  LanesRay r;
  r.ox = Lanes{o.x, o.x, o.x, o.x}, r.oy = Lanes{o.y, o.y, o.y, o.y}, r.oz = Lanes{o.z, o.z, o.z, o.z};
  r.dx = Lanes{d.x, d.x, d.x, d.x}, r.dy = Lanes{d.y, d.y, d.y, d.y}, r.dz = Lanes{d.z, d.z, d.z, d.z};
  r.a = Lanes{a, a, a, a};
  return r;
}

// Which of group k's four spheres get past intersect()'s two early exits: bit j for
// sphere 4k + j. Each line is the scalar code's expression, in its order of
// operations (glm's dot adds x, y, then z), so every lane rounds as the scalar code
// does; with a NaN every comparison is false there and here alike.
[[gnu::always_inline]] inline int candidates(const PackedSpheres& s, int k, const LanesRay& r) {
  const PackedSpheres::Group& g = s.groups[static_cast<std::size_t>(k)];
  Lanes x, y, z, r_squared;  // memcpy: unaligned loads
  std::memcpy(&x, g.x, sizeof x), std::memcpy(&y, g.y, sizeof y), std::memcpy(&z, g.z, sizeof z);
  std::memcpy(&r_squared, g.r_squared, sizeof r_squared);
  const Lanes oc_x = r.ox - x, oc_y = r.oy - y, oc_z = r.oz - z;
  const Lanes h = r.dx * oc_x + r.dy * oc_y + r.dz * oc_z;
  const Lanes c0 = (oc_x * oc_x + oc_y * oc_y + oc_z * oc_z) - r_squared;
  const Lanes zero = {0.0, 0.0, 0.0, 0.0};
  constexpr double m = -4 * std::numeric_limits<double>::epsilon();
  const Lanes minus_4_eps = {m, m, m, m};
  const auto behind = (c0 > zero) & (h > zero);  // per lane: all bits set (true) or none
  const auto outside = (h * h - r.a * c0) < (minus_4_eps * h * h);
  const auto rejected = behind | outside;
  // The four verdicts in an int at once (SSE2's movmskpd): a loop over the lanes would
  // move each one out of the vector register on its own.
  return static_cast<int>(~simd::lane_mask(rejected) & 0xf);
}

}  // namespace

PackedSpheres pack(const std::vector<Sphere>& spheres) {
  PackedSpheres packed;
  packed.count = static_cast<int>(spheres.size());
  for (std::size_t first = 0; first < spheres.size(); first += width) {
    PackedSpheres::Group g;
    for (std::size_t j = 0; j < width; ++j) {
      const Sphere& s = spheres[first + j < spheres.size() ? first + j : first];
      g.x[j] = s.center.x, g.y[j] = s.center.y, g.z[j] = s.center.z, g.r_squared[j] = s.radius * s.radius;
    }
    packed.groups.push_back(g);
  }
  return packed;
}

// Compiled twice, for AVX2 and for the baseline, where the toolchain can pick one as
// the program starts (simd.hpp says where).
GI_FOUR_DOUBLES_KERNEL void closest_sphere(const PackedSpheres& packed, const std::vector<Sphere>& spheres, Ray& ray,
                                           std::optional<Hit>& nearest) {
  const LanesRay lanes = spread(ray);
  for (int k = 0; width * k < packed.count; ++k) {
    const int maybe = candidates(packed, k, lanes);
    if (maybe == 0) continue;  // the common case: all four missed
    for (int j = 0; j < width; ++j) {
      const int i = width * k + j;
      if (!(maybe >> j & 1) || i >= packed.count) continue;
      if (auto hit = intersect(ray, spheres[static_cast<std::size_t>(i)])) {
        ray.t_max = hit->t;
        nearest = hit;
        nearest->object = i;
      }
    }
  }
}

GI_FOUR_DOUBLES_KERNEL int any_sphere(const PackedSpheres& packed, const std::vector<Sphere>& spheres, const Ray& ray) {
  const LanesRay lanes = spread(ray);
  for (int k = 0; width * k < packed.count; ++k) {
    const int maybe = candidates(packed, k, lanes);
    if (maybe == 0) continue;
    for (int j = 0; j < width; ++j) {
      const int i = width * k + j;
      if ((maybe >> j & 1) && i < packed.count && intersect(ray, spheres[static_cast<std::size_t>(i)])) return i;
    }
  }
  return -1;
}

}  // namespace gi
