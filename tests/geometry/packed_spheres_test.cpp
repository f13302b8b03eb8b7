#include "gi/geometry/packed_spheres.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "gi/core/rng.hpp"

using gi::Hit;
using gi::Ray;
using gi::Sphere;
using gi::vec3;

namespace {

// The plain loop the packed one stands in for: every sphere, in order, each hit
// shortening the ray.
std::optional<Hit> plain_closest(const std::vector<Sphere>& spheres, Ray ray) {
  std::optional<Hit> nearest;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (auto hit = gi::intersect(ray, spheres[i])) {
      ray.t_max = hit->t;
      nearest = hit;
      nearest->object = static_cast<int>(i);
    }
  return nearest;
}

int plain_any(const std::vector<Sphere>& spheres, const Ray& ray) {
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (gi::intersect(ray, spheres[i])) return static_cast<int>(i);
  return -1;
}

// The same double to the bit; any two NaNs count as the same (which NaN an operation
// with a NaN operand returns depends on the operand order the compiler chose).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }
bool same_bits(const vec3& a, const vec3& b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

vec3 random_point(gi::Rng& rng, double half_width) {
  return {half_width * (2 * rng.uniform() - 1), half_width * (2 * rng.uniform() - 1),
          half_width * (2 * rng.uniform() - 1)};
}

// The two loops must give the same hit to the last bit (t, point, normal, which
// sphere) and the same first blocker; `what` names the case in a failure.
void expect_same(const std::vector<Sphere>& spheres, const Ray& ray, const std::string& what) {
  const gi::PackedSpheres packed = gi::pack(spheres);
  Ray packed_ray = ray;
  std::optional<Hit> packed_hit;
  gi::closest_sphere(packed, spheres, packed_ray, packed_hit);
  const std::optional<Hit> plain = plain_closest(spheres, ray);
  ASSERT_EQ(packed_hit.has_value(), plain.has_value()) << what;
  if (plain) {
    EXPECT_TRUE(same_bits(packed_hit->t, plain->t)) << what << ": t " << packed_hit->t << " against " << plain->t;
    EXPECT_TRUE(same_bits(packed_hit->point, plain->point)) << what;
    EXPECT_TRUE(same_bits(packed_hit->normal, plain->normal)) << what;
    EXPECT_EQ(packed_hit->object, plain->object) << what;
    EXPECT_TRUE(same_bits(packed_ray.t_max, plain->t)) << what << ": the hit shortens the ray";
  }
  EXPECT_EQ(gi::any_sphere(packed, spheres, ray), plain_any(spheres, ray)) << what;
}

}  // namespace

// Random scenes of 1 to 13 spheres (every remainder of 4, so the last group's empty
// lanes are exercised) and random rays, many starting inside a sphere, some with
// short ranges and unnormalised directions: the packed loop must agree with the
// plain one bit for bit, hit or miss, in every case.
TEST(PackedSpheres, AgreesBitForBitWithThePlainLoop) {
  int hits = 0, misses = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    gi::Rng rng(seed, 7);
    std::vector<Sphere> spheres;
    const int n = 1 + static_cast<int>(rng.uniform() * 13);
    for (int i = 0; i < n; ++i) spheres.push_back(Sphere{random_point(rng, 5), 0.05 + 2 * rng.uniform(), i});
    for (int r = 0; r < 50; ++r) {
      Ray ray{random_point(rng, 6), random_point(rng, 1) * (r % 5 == 0 ? 3.7 : 1.0)};
      if (r % 3 == 0) ray.direction = gi::normalize(ray.direction);
      if (r % 7 == 0) ray.t_max = 4 * rng.uniform();
      if (r % 11 == 0) ray.t_min = 1e-6;
      expect_same(spheres, ray, "seed " + std::to_string(seed) + ", ray " + std::to_string(r));
      (plain_closest(spheres, ray) ? hits : misses) += 1;
    }
  }
  EXPECT_GT(hits, 2000) << "the cases should hit often";
  EXPECT_GT(misses, 2000) << "and miss often";
}

// The cases the early exits exist for: a small sphere far away (where the textbook
// discriminant cancels), a ray grazing a sphere, a sphere just behind the origin, a
// ray starting on a surface, and a NaN direction (every comparison false).
TEST(PackedSpheres, AgreesOnTheEdgeCasesOfTheEarlyExits) {
  const std::vector<Sphere> spheres{{{0, 0, -1e6}, 1e-3, 0}, {{0, 1, -5}, 1, 1},      {{0, 0, 2}, 1, 2},
                                    {{3, 0, 0}, 1, 3},       {{0, -2, -3}, 1e-9, 4}, {{1e8, 0, 0}, 1e7, 5}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Ray rays[] = {{{0, 0, 0}, {0, 0, -1}},   {{0, 1e-3, 0}, {0, 0, -1}}, {{0, 1.001e-3, 0}, {0, 0, -1}},
                      {{0, 0, 0}, {0, 1, -5}},   {{0, 2, 0}, {0, 0, -1}},    {{0, 0, 1}, {0, 0, 1}},
                      {{2, 0, 0}, {1, 0, 0}},    {{2, 0, 0}, {-1, 0, 0}},    {{0, 0, 0}, {0, -2, -3}},
                      {{0, 0, 0}, {nan, 0, -1}}, {{0, 0, 0}, {1, 0, 0}},     {{nan, 0, 0}, {0, 0, -1}}};
  for (std::size_t i = 0; i < std::size(rays); ++i) expect_same(spheres, rays[i], "edge case " + std::to_string(i));
}

TEST(PackedSpheres, NoSpheresNoHit) {
  const std::vector<Sphere> none;
  Ray ray{{0, 0, 0}, {0, 0, -1}};
  std::optional<Hit> hit;
  gi::closest_sphere(gi::pack(none), none, ray, hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(gi::any_sphere(gi::pack(none), none, ray), -1);
}
