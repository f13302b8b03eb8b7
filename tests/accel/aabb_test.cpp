#include "gi/geometry/aabb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gi/core/rng.hpp"

using gi::Aabb;
using gi::Ray;
using gi::vec3;

namespace {

const double inf = std::numeric_limits<double>::infinity();
const Aabb unit{{0, 0, 0}, {1, 1, 1}};

std::optional<double> slab(const Ray& ray, const Aabb& box) { return gi::slab_test(ray, 1.0 / ray.direction, box); }

// The slab test written the long way, for comparison: a division per slab, and an
// explicit case for rays parallel to it.
std::optional<double> reference(const Ray& ray, const Aabb& box) {
  double t_enter = ray.t_min, t_exit = ray.t_max;
  for (int a = 0; a < 3; ++a) {
    if (ray.direction[a] == 0) {
      if (ray.origin[a] < box.lo[a] || ray.origin[a] > box.hi[a]) return std::nullopt;
      continue;
    }
    const double t0 = (box.lo[a] - ray.origin[a]) / ray.direction[a];
    const double t1 = (box.hi[a] - ray.origin[a]) / ray.direction[a];
    t_enter = std::max(t_enter, std::min(t0, t1));
    t_exit = std::min(t_exit, std::max(t0, t1));
  }
  if (t_enter > t_exit) return std::nullopt;
  return t_enter;
}

}  // namespace

TEST(Aabb, EmptyBoxGrowsToWhatItIsGiven) {
  Aabb box;
  EXPECT_TRUE(gi::is_empty(box));
  EXPECT_EQ(gi::surface_area(box), 0.0);
  gi::grow(box, vec3(1, 2, 3));
  EXPECT_FALSE(gi::is_empty(box));
  EXPECT_EQ(box.lo, vec3(1, 2, 3));
  EXPECT_EQ(box.hi, vec3(1, 2, 3));
  gi::grow(box, vec3(-1, 4, 3));
  EXPECT_EQ(box.lo, vec3(-1, 2, 3));
  EXPECT_EQ(box.hi, vec3(1, 4, 3));
  EXPECT_EQ(gi::surface_area(box), 8.0);  // flat: both sides of a 2 x 2 square
  EXPECT_EQ(gi::centroid(box), vec3(0, 3, 3));
}

TEST(Aabb, SurfaceAreaAndSurrounding) {
  const Aabb box{{0, 0, 0}, {1, 2, 3}};
  EXPECT_DOUBLE_EQ(gi::surface_area(box), 2 * (2 + 6 + 3));
  const Aabb flat{{0, 0, 0}, {2, 3, 0}};
  EXPECT_DOUBLE_EQ(gi::surface_area(flat), 2 * 6);  // a quad's box: both sides count
  const Aabb both = gi::surrounding(box, Aabb{{-1, 5, 1}, {0, 6, 2}});
  EXPECT_EQ(both.lo, vec3(-1, 0, 0));
  EXPECT_EQ(both.hi, vec3(1, 6, 3));
  EXPECT_EQ(gi::surrounding(Aabb{}, box).lo, box.lo);
}

TEST(Aabb, BoundsOfSphereAndQuad) {
  const Aabb s = gi::bounds(gi::Sphere{{1, 2, 3}, 0.5, 0});
  EXPECT_EQ(s.lo, vec3(0.5, 1.5, 2.5));
  EXPECT_EQ(s.hi, vec3(1.5, 2.5, 3.5));
  // A tilted, sheared quad: the box of its four corners, not of corner + edges.
  const Aabb q = gi::bounds(gi::Quad{{1, 0, 0}, {2, 1, -1}, {-3, 2, 0.5}, 0});
  EXPECT_EQ(q.lo, vec3(-2, 0, -1));
  EXPECT_EQ(q.hi, vec3(3, 3, 0.5));
  const Aabb wall = gi::bounds(gi::Quad{{0, 0, 2}, {1, 0, 0}, {0, 1, 0}, 0});
  EXPECT_EQ(wall.lo.z, 2.0);  // flat, as an axis-aligned quad's box is
  EXPECT_EQ(wall.hi.z, 2.0);
}

TEST(SlabTest, EntersAtTheNearFace) {
  const auto t = slab(Ray{{-2, 0.5, 0.5}, {1, 0, 0}}, unit);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(*t, 2.0);
  const auto diagonal = slab(Ray{{-1, -1, -1}, gi::normalize(vec3(1, 1, 1))}, unit);
  ASSERT_TRUE(diagonal);
  EXPECT_NEAR(*diagonal, std::sqrt(3.0), 1e-12);
  EXPECT_FALSE(slab(Ray{{-2, 1.5, 0.5}, {1, 0, 0}}, unit));
}

TEST(SlabTest, NegativeDirectionsMeetTheHighFaceFirst) {
  const auto t = slab(Ray{{3, 0.5, 0.5}, {-1, 0, 0}}, unit);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(*t, 2.0);
  // o - s (1, 2, 3) is in the x slab for s in [0.5, 1.5], y [0.75, 1.25], z [2/3, 1].
  const auto all = slab(Ray{{1.5, 2.5, 3}, gi::normalize(vec3(-1, -2, -3))}, unit);
  ASSERT_TRUE(all);
  EXPECT_NEAR(*all, 0.75 * std::sqrt(14.0), 1e-12);  // in through the face y = 1
}

TEST(SlabTest, ParallelRaysInsideOrOutsideTheSlab) {
  EXPECT_TRUE(slab(Ray{{-1, 0.5, 0.5}, {1, 0, 0}}, unit));
  EXPECT_FALSE(slab(Ray{{-1, 1.5, 0.5}, {1, 0, 0}}, unit));
  EXPECT_FALSE(slab(Ray{{-1, -0.5, 0.5}, {1, 0, 0}}, unit));
  EXPECT_FALSE(slab(Ray{{-1, 0.5, -0.5}, {1, -0.0, 0}}, unit));  // -0.0 gives inv_dir = -inf
  EXPECT_TRUE(slab(Ray{{-1, 0.5, 0.5}, {1, -0.0, -0.0}}, unit));
}

TEST(SlabTest, RayInAFacePlaneHitsWithoutNaN) {
  // Origin exactly on a slab's plane and direction 0 in that axis: (lo - o) * inv_dir
  // is 0 * inf = NaN. The box is closed, so this is a hit, entered at the near face.
  for (const double y : {0.0, 1.0})
    for (const double dy : {0.0, -0.0}) {
      const auto t = slab(Ray{{-2, y, 0.5}, {1, dy, 0}}, unit);
      ASSERT_TRUE(t) << "y = " << y << ", dy = " << dy;
      EXPECT_EQ(*t, 2.0);
    }
  const auto edge = slab(Ray{{-2, 1, 1}, {1, 0, 0}}, unit);  // along an edge
  ASSERT_TRUE(edge);
  EXPECT_EQ(*edge, 2.0);
  const Aabb flat{{0, 0, 3}, {1, 1, 3}};  // a floor quad's box, the ray in its plane
  EXPECT_TRUE(slab(Ray{{-2, 0.5, 3}, {1, 0, 0}}, flat));
}

TEST(SlabTest, RayStartingInsideEntersAtTMin) {
  const auto t = slab(Ray{{0.5, 0.5, 0.5}, {0, 0, 1}}, unit);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 0.0);
  const auto later = slab(Ray{{0.5, 0.5, 0.5}, {0, 0, 1}, 0.25, inf}, unit);
  ASSERT_TRUE(later);
  EXPECT_EQ(*later, 0.25);
  EXPECT_FALSE(slab(Ray{{0.5, 0.5, 0.5}, {0, 0, 1}, 0.6, inf}, unit));  // t_min beyond the exit
}

TEST(SlabTest, BoxBehindTheRayOrBeyondTMaxMisses) {
  EXPECT_FALSE(slab(Ray{{0.5, 0.5, 3}, {0, 0, 1}}, unit));
  EXPECT_FALSE(slab(Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, 1.5}, unit));
  const auto touching = slab(Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, 2}, unit);  // t_max exactly at the face
  ASSERT_TRUE(touching);
  EXPECT_EQ(*touching, 2.0);
}

TEST(SlabTest, ARayCutAtAQuadsHitEntersItsFlatBox) {
  // Rays from the origin to the square z = 3, each ending exactly at its hit. The box's
  // crossing 3 * (1 / d.z) is rounded otherwise than the quad's t: for some of these
  // rays it lands past t_max, and only box_reach keeps the box (and the hit) in.
  const gi::Quad square{{-1, -1, 3}, {2, 0, 0}, {0, 2, 0}, 0};
  int past = 0;
  for (int i = 1; i <= 30; ++i)
    for (int j = 1; j <= 30; ++j) {
      Ray ray{{0, 0, 0}, gi::normalize(vec3(0.01 * i, 0.01 * j, 1))};
      ray.t_max = gi::intersect(ray, square)->t;
      past += 3 * (1 / ray.direction.z) > ray.t_max;
      EXPECT_TRUE(slab(ray, gi::bounds(square))) << i << ", " << j;
    }
  EXPECT_GT(past, 30) << "the crossing should round past t_max for some rays, or this tests nothing";
  // A box a millionth beyond t_max stays out: the reach is a rounding's, not a distance.
  EXPECT_FALSE(slab(Ray{{0.5, 0.5, 3}, {0, 0, -1}, 0, 2 - 1e-6}, unit));
}

TEST(SlabTest, FlatBoxesAndGrazingRays) {
  const Aabb flat{{0, 0, 3}, {1, 1, 3}};
  const auto through = slab(Ray{{0.5, 0.5, 0}, {0, 0, 1}}, flat);
  ASSERT_TRUE(through);  // entry equals exit: still a hit
  EXPECT_EQ(*through, 3.0);
  // Passing the corner (1, 1) on the outside: the ray crosses each slab, but leaves
  // y's before it enters x's (s in [0, 0.5] against [0.6, 1.6]).
  EXPECT_FALSE(slab(Ray{{1.6, 0, 0.5}, gi::normalize(vec3(-1, 2, 0))}, unit));
  EXPECT_TRUE(slab(Ray{{1, -1, 0.5}, {0, 1, 0}}, unit));  // along the face x = 1
}

TEST(SlabTest, AgreesWithTheLongWayOnRandomRays) {
  gi::Rng rng(11);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const vec3 a(rng.uniform(), rng.uniform(), rng.uniform()), b(rng.uniform(), rng.uniform(), rng.uniform());
    const Aabb box{4.0 * glm::min(a, b) - 2.0, 4.0 * glm::max(a, b) - 2.0};
    const vec3 origin(6 * rng.uniform() - 3, 6 * rng.uniform() - 3, 6 * rng.uniform() - 3);
    const vec3 target = box.lo + (box.hi - box.lo) * vec3(rng.uniform(), rng.uniform(), rng.uniform());
    vec3 d = i % 2 ? target - origin : vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
    if (i % 4 == 0) d[static_cast<int>(rng.below(3))] = 0;  // some parallel rays
    const Ray ray{origin, d, 0.1 * rng.uniform(), i % 3 == 0 ? 2 * rng.uniform() : inf};
    const auto t = slab(ray, box), expected = reference(ray, box);
    ASSERT_EQ(t.has_value(), expected.has_value()) << "case " << i;
    if (t) {
      EXPECT_NEAR(*t, *expected, 1e-12 * (1 + *expected)) << "case " << i;
    }
    hits += t.has_value();
  }
  EXPECT_GT(hits, 5000);  // the cases are not all misses
}
