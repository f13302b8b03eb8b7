#include "gi/geometry/quad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gi/core/rng.hpp"

using gi::Quad;
using gi::Ray;
using gi::vec3;

namespace {
// A 2 x 1 parallelogram, sheared, in the plane z = 0, facing +z.
const Quad quad{{0, 0, 0}, {2, 0, 0}, {0.5, 1, 0}, 0};
}

TEST(Quad, AreaNormalAndCentre) {
  EXPECT_DOUBLE_EQ(gi::area(quad), 2.0);
  EXPECT_EQ(gi::normal(quad), vec3(0, 0, 1));
  EXPECT_EQ(gi::centre(quad), vec3(1.25, 0.5, 0));
}

TEST(Quad, HitInsideMissOutsideEvenWithinTheBoundingBox) {
  const auto hit = gi::intersect(Ray{{1.25, 0.5, 3}, {0, 0, -1}}, quad);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 3.0);
  EXPECT_EQ(hit->normal, vec3(0, 0, 1));
  // (0.1, 0.9) is inside the box [0, 2.5] x [0, 1] but left of the sheared edge.
  EXPECT_FALSE(gi::intersect(Ray{{0.1, 0.9, 3}, {0, 0, -1}}, quad));
  EXPECT_FALSE(gi::intersect(Ray{{2.4, 0.1, 3}, {0, 0, -1}}, quad));
}

TEST(Quad, ParallelRayMisses) { EXPECT_FALSE(gi::intersect(Ray{{1, 0.5, 1}, {1, 0, 0}}, quad)); }

TEST(Quad, DegenerateQuadsAreRejected) {
  EXPECT_THROW(gi::check(Quad{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0}), std::invalid_argument);
  EXPECT_THROW(gi::check(Quad{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 0}), std::invalid_argument);
  EXPECT_NO_THROW(gi::check(quad));
}

// crossing() and hit_at() (the fast walk's leaf test) against intersect(): the same
// verdict for every ray, and where it hits, the same Hit to the bit. The rays are aimed
// where a verdict is closest to turning: at the edges and corners (s or u exactly 0 or
// 1, and a hair either side), grazing the plane, lying in it (a NaN t), and cut exactly
// at their hit by t_max or t_min, or a hair short of it.
TEST(Quad, CrossingGivesIntersectsVerdictAndHitToTheBit) {
  const Quad quads[] = {quad, Quad{{1, -2, 0.5}, {0, 3, 1}, {-2, 0, 1}, 4}, Quad{{-1e3, 7, 2}, {1e-3, 0, 0}, {0, 0, 2e3}, 1}};
  gi::Rng rng(7);
  int hits = 0, misses = 0;
  for (const Quad& q : quads) {
    const vec3 n = gi::normal(q);
    for (int i = 0; i < 20000; ++i) {
      // (s, u): inside, on an edge, or a hair outside it.
      const double edges[] = {0.0, 1.0, -1e-16, 1 + 1e-16, rng.uniform()};
      const double s = i % 3 == 0 ? edges[i % 5] : 1.2 * rng.uniform() - 0.1;
      const double u = i % 5 == 0 ? edges[(i / 5) % 5] : 1.2 * rng.uniform() - 0.1;
      const vec3 target = q.corner + s * q.edge_u + u * q.edge_v;
      vec3 from = target + (2 * rng.uniform() - 1) * 3.0 * n + vec3(rng.uniform(), rng.uniform(), rng.uniform());
      if (i % 11 == 0) from = target + q.edge_u * (1 + rng.uniform());  // in the plane: d.n = 0
      if (i % 13 == 0) from = target + q.edge_u + 1e-13 * n;             // grazing
      Ray ray{from, gi::normalize(target - from)};
      if (i % 7 == 0 || i % 7 == 1) {  // cut at the hit (t_max, t_min) or a hair short of it
        if (const auto full = gi::intersect(ray, q)) {
          const double t = i % 14 < 7 ? full->t : std::nextafter(full->t, 0.0);
          (i % 7 == 0 ? ray.t_max : ray.t_min) = t;
          if (i % 7 == 1) ray.t_max = 2 * t + 1;
        }
      }
      const auto expected = gi::intersect(ray, q);
      const gi::QuadCrossing x = gi::crossing(ray, q);
      ASSERT_EQ(x.hit, expected.has_value()) << "quad " << (&q - quads) << ", ray " << i;
      if (!expected) {
        ++misses;
        continue;
      }
      ++hits;
      const gi::Hit hit = gi::hit_at(ray, q, x.t);
      EXPECT_EQ(x.t, expected->t) << "ray " << i;
      EXPECT_EQ(hit.t, expected->t);
      EXPECT_EQ(hit.point, expected->point) << "ray " << i;
      EXPECT_EQ(hit.normal, expected->normal) << "ray " << i;
      EXPECT_EQ(hit.material, expected->material);
    }
  }
  EXPECT_GT(hits, 10000) << "the rays should hit as well as miss";
  EXPECT_GT(misses, 10000);
}
