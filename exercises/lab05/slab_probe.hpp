// What the tests of exercise 5.2 need of exercise 5.1: closest_hit calls the slab
// test, so a test whose scene needs more of it than a student's gives checks that
// first and fails with that message, not one about the traversal.
#pragma once
#include <cmath>
#include <string>

#include "gi/core/ray.hpp"
#include "gi/geometry/aabb.hpp"
#include "gi/geometry/quad.hpp"

namespace lab05 {

// What the traversal needs of exercise 5.1, as a message ("" when all is well).
// `level`: 0 rays along +z into a box ahead; 1 also the distance where the ray enters
// (by which children are ordered and skipped); 2 also rays with negative components;
// 3 also flat boxes (those of axis-aligned quads); 4 also a ray cut exactly at its hit
// on a flat box's quad (t_max = the quad's t), which must enter that box.
inline std::string slab_test_problem(int level) {
  const gi::Aabb box{{1, 1, 1}, {3, 2, 4}};
  const auto slab = [](const gi::Ray& r, const gi::Aabb& b) { return gi::slab_test(r, 1.0 / r.direction, b); };
  const std::string fix = " -- closest_hit relies on your slab test (exercise 5.1): make its tests pass first";
  if (!slab(gi::Ray{{2, 1.5, -3}, {0, 0, 1}}, box)) return "your slab test misses a box straight ahead" + fix;
  if (slab(gi::Ray{{5, 1.5, -3}, {0, 0, 1}}, box)) return "your slab test hits a box beside the ray" + fix;
  if (level >= 1) {
    const auto t = slab(gi::Ray{{2, 1.5, -3}, {0, 0, 1}}, box);
    if (!t || std::abs(*t - 4) > 1e-12) return "your slab test gives the wrong distance to a box ahead" + fix;
  }
  if (level >= 2 && !slab(gi::Ray{{2, 1.5, 9}, {0, 0, -1}}, box))
    return "your slab test misses a box ahead of a ray going towards -z" + fix;
  if (level >= 3 && !slab(gi::Ray{{1, 3, 1}, {0, -1, 0}}, gi::Aabb{{0, 0, 0}, {2, 0, 2}}))
    return "your slab test misses a flat box (the box of an axis-aligned quad)" + fix;
  if (level >= 4) {
    const gi::Quad square{{-1, -1, 3}, {2, 0, 0}, {0, 2, 0}, 0};
    for (int i = 1; i <= 30; ++i) {
      gi::Ray ray{{0, 0, 0}, gi::normalize(gi::vec3(0.01 * i, 0.08, 1))};
      ray.t_max = gi::intersect(ray, square)->t;
      if (!slab(ray, gi::bounds(square))) return "your slab test misses a box where the ray ends exactly at its hit" + fix;
    }
  }
  return "";
}

// What a test of skipping needs of exercise 5.1 besides `level` 1: a box the ray
// enters beyond its t_max is a miss (pitfall 3), as a message ("" when all is well).
inline std::string slab_test_t_max_problem() {
  const gi::Ray cut_short{{2, 1.5, -3}, {0, 0, 1}, 0, 3};  // would enter the box at t = 4
  if (gi::slab_test(cut_short, 1.0 / cut_short.direction, gi::Aabb{{1, 1, 1}, {3, 2, 4}}))
    return "your slab test lets in a box the ray enters beyond its t_max -- closest_hit relies on your slab test "
           "(exercise 5.1): make its tests pass first";
  return "";
}

}  // namespace lab05

// Stops a test whose scene needs more of the slab test than yours gives, saying so.
#define NEEDS_SLAB_TEST(level)                                   \
  do {                                                           \
    const std::string problem = lab05::slab_test_problem(level); \
    ASSERT_TRUE(problem.empty()) << problem;                     \
  } while (false)
