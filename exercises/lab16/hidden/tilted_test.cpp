// Hidden graded tests of lab 16 (the autograder's): the gather from a wall, whose
// normal is not the y axis, and a full furnace through both passes. One point per test.
#include <cmath>

#include <gtest/gtest.h>

#include "gi/twopass/final_gather.hpp"
#include "lab16/room.hpp"
#include "support/print.hpp"

using gi::vec3;
using lab16::constant;

TEST(Ex16_2_GatherOnAWall, TheOppositeWallGivesItsFormFactor) {
  // From the centre of the wall x = 0 (normal +x), only the wall x = 1 reflects (B - E = 1):
  // H = F to a unit square at distance 1 centred opposite = 4 F_corner(0.5, 0.5, 1).
  const gi::RadiosityHandoff h = lab16::room_handoff(
      lab16::room_mesh(), [](int s, const vec3&) { return constant(s == 3 ? 1 : 0); },
      [](int, const vec3&) { return constant(0); }, [](int, const vec3&) { return constant(0); });
  const gi::EyeWorld eye = gi::make_eye_world(h.mesh, {});
  double sum = 0, sum2 = 0;
  const int runs = 40;
  for (int seed = 1; seed <= runs; ++seed) {
    gi::Rng rng(seed, 61);
    const double v = gi::final_gather(eye, h, vec3(1e-9, 0.5, 0.5), vec3(1, 0, 0), 8, rng).y;
    sum += v, sum2 += v * v;
  }
  const double mean = sum / runs, se = std::sqrt(std::max(0.0, sum2 / runs - mean * mean) / (runs - 1));
  const double F = 4 * lab16::point_to_corner_rectangle(0.5, 0.5, 1.0);
  EXPECT_NEAR(mean, F, 5 * se + 1e-3) << "gathering at a wall: the cosine-weighted directions must be turned "
                                         "about the point's own normal n (an orthonormal frame built from n)";
}

TEST(Ex16_1_HandoffFlat, AConstantPartReadsTheSameEverywhere) {
  const gi::RadiosityHandoff h = lab16::room_handoff(
      lab16::room_mesh(), [](int, const vec3&) { return constant(4); }, [](int, const vec3&) { return constant(1); },
      [](int, const vec3&) { return constant(0.5); });
  for (int e = 0; e < static_cast<int>(h.mesh.elements.size()); e += 7) {
    const auto& c = h.mesh.elements[e].shape.corners;
    EXPECT_NEAR(gi::indirect_radiosity_at(h, e, c[0]).y, 2.5, 1e-9)
        << "B - E - D = 4 - 0.5 - 1 on every element: every vertex, and so every point, reads 2.5";
  }
}
