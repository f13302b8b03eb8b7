// Graded tests of exercise 5.1: the ray-box slab test. One point per test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gi/geometry/aabb.hpp"
#include "gi/geometry/quad.hpp"
#include "support/print.hpp"

using gi::Aabb;
using gi::Ray;
using gi::vec3;

namespace {
const double inf = std::numeric_limits<double>::infinity();
const Aabb box{{1, 1, 1}, {3, 2, 4}};

std::optional<double> slab(const Ray& ray, const Aabb& b = box) { return gi::slab_test(ray, 1.0 / ray.direction, b); }
}  // namespace

TEST(Ex5_1_SlabTest, HitsABoxInFront) {
  const auto t = slab(Ray{{2, 1.5, -3}, {0, 0, 1}});
  ASSERT_TRUE(t) << "the ray (2, 1.5, -3) + t (0, 0, 1) runs straight into the box [1,3]x[1,2]x[1,4]";
  EXPECT_NEAR(*t, 4.0, 1e-12) << "return where the ray enters the box: the largest of the three slabs' entries";
}

TEST(Ex5_1_SlabTest, MissesABoxBesideTheRay) {
  EXPECT_FALSE(slab(Ray{{5, 1.5, -3}, {0, 0, 1}})) << "x = 5 is outside the slab 1 <= x <= 3 for every t";
  EXPECT_FALSE(slab(Ray{{2, 1.5, -3}, {0, 1, 0}})) << "this ray runs along y and never reaches z = 1";
}

TEST(Ex5_1_SlabTest, NegativeDirectionsMeetTheHighPlaneFirst) {
  const auto t = slab(Ray{{2, 1.5, 9}, {0, 0, -1}});
  ASSERT_TRUE(t) << "a ray going towards -z meets z = hi.z = 4 first and z = lo.z = 1 second: when inv_dir < 0, "
                    "swap the two crossings so that t_near <= t_far";
  EXPECT_NEAR(*t, 5.0, 1e-12) << "entering through z = 4 from z = 9 takes t = 5";
  const auto all = slab(Ray{{6, 5, 7}, gi::normalize(vec3(-3, -3, -3))});
  ASSERT_TRUE(all) << "a ray with every direction component negative must hit too";
  EXPECT_NEAR(*all, 3 * std::sqrt(3.0), 1e-9) << "(6,5,7) - s (1,1,1) enters at s = 3, through x = 3 and y = 2 "
                                                 "and z = 4";
}

TEST(Ex5_1_SlabTest, RayStartingInsideTheBoxHits) {
  const auto t = slab(Ray{{2, 1.5, 2}, {1, 0, 0}});
  ASSERT_TRUE(t) << "a ray that starts inside the box hits it (the box's entry is behind the origin, at t < 0): "
                    "start t_enter at ray.t_min, do not require the entry to be ahead of the origin";
  EXPECT_EQ(*t, 0.0) << "from inside, the entry within [t_min, t_max] is t_min itself, not a negative t";
}

TEST(Ex5_1_SlabTest, BoxBehindTheRayMisses) {
  EXPECT_FALSE(slab(Ray{{2, 1.5, 9}, {0, 0, 1}}))
      << "the box lies at t in [-8, -5], behind the origin: start the overlap at t_enter = ray.t_min, "
         "not at -infinity";
}

TEST(Ex5_1_SlabTest, RespectsTMax) {
  EXPECT_FALSE(slab(Ray{{2, 1.5, -3}, {0, 0, 1}, 0, 3.5}))
      << "the box starts at t = 4, beyond t_max = 3.5 (a nearer hit is already known): start t_exit at ray.t_max "
         "(times box_reach)";
  const auto t = slab(Ray{{2, 1.5, -3}, {0, 0, 1}, 0, 4.5});
  ASSERT_TRUE(t) << "t_max = 4.5 reaches into the box, which starts at t = 4";
  EXPECT_NEAR(*t, 4.0, 1e-12) << "the ray enters the box at t = 4";
}

TEST(Ex5_1_SlabTest, RespectsTMin) {
  EXPECT_FALSE(slab(Ray{{2, 1.5, -3}, {0, 0, 1}, 7.5, inf}))
      << "the ray is in the box for t in [4, 7], but it only starts at t_min = 7.5";
  const auto t = slab(Ray{{2, 1.5, -3}, {0, 0, 1}, 5, inf});
  ASSERT_TRUE(t) << "at t_min = 5 the ray is inside the box";
  EXPECT_NEAR(*t, 5.0, 1e-12) << "the entry is clipped to t_min";
}

TEST(Ex5_1_SlabTest, ParallelRayInsideTheSlabHitsOutsideMisses) {
  const auto t = slab(Ray{{0, 1.5, 2}, {1, 0, 0}});
  ASSERT_TRUE(t) << "direction (1, 0, 0) is parallel to the y and z slabs; the origin is inside both, so they do "
                    "not limit t (inv_dir = +inf gives t = -inf and +inf there, which is right)";
  EXPECT_NEAR(*t, 1.0, 1e-12) << "the ray enters through x = 1 at t = 1";
  EXPECT_FALSE(slab(Ray{{0, 2.5, 2}, {1, 0, 0}})) << "y = 2.5 is outside 1 <= y <= 2 for every t: a miss";
  EXPECT_FALSE(slab(Ray{{0, 0.5, 2}, {1, -0.0, 0}})) << "direction y = -0.0 gives inv_dir = -inf; the ray is still "
                                                        "parallel, and y = 0.5 is outside the slab";
}

TEST(Ex5_1_SlabTest, RayInAFacePlaneHitsWithoutNaN) {
  // The origin lies exactly on a slab's plane and the ray runs parallel to it.
  for (const double y : {1.0, 2.0})
    for (const double dy : {0.0, -0.0}) {
      const auto t = slab(Ray{{0, y, 2}, {1, dy, 0}});
      ASSERT_TRUE(t) << "origin y = " << y << " on the face y = " << y << ", direction y = " << dy
                     << ": (lo - o) * inv_dir is 0 * inf = NaN. Make sure a NaN never becomes t_enter or t_exit "
                        "(every comparison with NaN is false: `if (t_near > t_enter) t_enter = t_near` skips it), "
                        "or treat direction 0 as its own case. The box is closed: this ray touches it";
      EXPECT_FALSE(std::isnan(*t)) << "the entry distance is NaN";
      EXPECT_NEAR(*t, 1.0, 1e-12) << "the ray enters through x = 1 at t = 1";
    }
}

TEST(Ex5_1_SlabTest, FlatBoxIsHit) {
  const Aabb floor_quad{{0, 0, 0}, {2, 0, 2}};  // the box of a quad lying in y = 0: no thickness
  const auto t = slab(Ray{{1, 3, 1}, {0, -1, 0}}, floor_quad);
  ASSERT_TRUE(t) << "the box of an axis-aligned quad is flat: the ray enters and leaves it at the same t. Test "
                    "t_enter > t_exit for a miss, not t_enter >= t_exit";
  EXPECT_NEAR(*t, 3.0, 1e-12) << "the flat box lies 3 below the ray's origin";
}

TEST(Ex5_1_SlabTest, AllThreeSlabsAtOnce) {
  // Along (0.5, -2, 2) + s (1, 1, 0) the ray is in the x slab for s in [0.5, 2.5] and
  // in the y slab for s in [3, 4]: in each, but never in both at once.
  EXPECT_FALSE(slab(Ray{{0.5, -2, 2}, gi::normalize(vec3(1, 1, 0))}))
      << "the ray passes outside the box's corner (3, 1): it leaves the x slab before it enters the y slab. The "
         "box is where all three slabs' intervals overlap: the largest entry and the smallest exit, and a miss "
         "when the entry comes after the exit";
}

TEST(Ex5_1_SlabTest, ARayCutAtItsHitStillEntersTheBox) {
  // A shadow ray to a point on a surface ends exactly there: t_max = the quad's own t.
  // The flat box of the square z = 3 must let it in, although its crossing
  // (3 - 0) * inv_dir.z rounds to just past that t for about one ray in six of these.
  const gi::Quad square{{-1, -1, 3}, {2, 0, 0}, {0, 2, 0}, 0};
  for (int i = 1; i <= 30; ++i)
    for (int j = 1; j <= 30; ++j) {
      Ray ray{{0, 0, 0}, gi::normalize(vec3(0.01 * i, 0.01 * j, 1))};
      ray.t_max = gi::intersect(ray, square)->t;
      ASSERT_TRUE(slab(ray, gi::bounds(square)))
          << "the ray from the origin towards (" << i << "/100, " << j << "/100, 1) ends exactly at its hit on "
          << "the square z = 3, t = " << ray.t_max << ": start t_exit at ray.t_max * box_reach (aabb.hpp), a hair "
          << "further, since the box's crossing is rounded differently from the quad's t and can land just past it";
    }
}
