// Graded tests of exercise 16.2: the final-gather estimate. One point per test.
// Random estimates are tested over 40 seeds against a closed form, within 5 standard
// errors of their mean: a correct gather fails by chance about once in 10^6 runs.
#include <cmath>

#include <gtest/gtest.h>

#include "gi/twopass/final_gather.hpp"
#include "room.hpp"
#include "support/print.hpp"

using gi::Color;
using gi::vec3;
using lab16::constant;

namespace {

const vec3 floor_centre(0.5, 1e-9, 0.5), up(0, 1, 0);

struct Estimate {
  double mean, standard_error;
};

// The red channel of final_gather at the floor's centre, over 40 seeds.
Estimate gather(const gi::RadiosityHandoff& h, int strata, const vec3& x = floor_centre, const vec3& n = up) {
  const gi::EyeWorld eye = gi::make_eye_world(h.mesh, {});
  const int runs = 40;
  double sum = 0, sum2 = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    gi::Rng rng(seed, 16);
    const double v = gi::final_gather(eye, h, x, n, strata, rng).x;
    sum += v, sum2 += v * v;
  }
  const double mean = sum / runs, var = std::max(0.0, (sum2 - runs * mean * mean) / (runs - 1));
  return {mean, std::sqrt(var / runs)};
}

// The ceiling alone reflects (B - E = value(centre)); the rest is black.
gi::RadiosityHandoff ceiling_only(const std::function<double(const vec3&)>& value, double ceiling_emission = 0) {
  return lab16::room_handoff(
      lab16::room_mesh(), [&](int s, const vec3& c) { return constant(s == 1 ? ceiling_emission + value(c) : 0); },
      [](int, const vec3&) { return constant(0); },
      [&](int s, const vec3&) { return constant(s == 1 ? ceiling_emission : 0); });
}

// F from the floor's centre to the whole ceiling (four rectangles of 0.5 x 0.5 at height 1).
double form_factor_to_ceiling() { return 4 * lab16::point_to_corner_rectangle(0.5, 0.5, 1.0); }

}  // namespace

TEST(Ex16_2_FinalGather, AUniformRoomGivesItsRadiosity) {
  // Every wall reflects B - E = 2 (the floor is a light besides, E = 3): the irradiance
  // is 2 whatever the directions, H = integral of (2 / pi) cos dw = 2.
  const gi::RadiosityHandoff h = lab16::room_handoff(
      lab16::room_mesh(), [](int s, const vec3&) { return constant(s == 0 ? 5 : 2); },
      [](int, const vec3&) { return constant(0); }, [](int s, const vec3&) { return constant(s == 0 ? 3 : 0); });
  const gi::EyeWorld eye = gi::make_eye_world(h.mesh, {});
  gi::Rng rng(7, 16);
  const Color H = gi::final_gather(eye, h, floor_centre, up, 4, rng);
  EXPECT_NEAR(H.x, 2.0, 1e-9) << "in a room whose walls all reflect B - E = 2 the gathered irradiance is exactly "
                                 "2: each ray's L cos / p = (B - E) / pi * cos / (cos / pi) = B - E; average over "
                                 "all strata^2 rays";
  EXPECT_NEAR(H.z, 2.0, 1e-9) << "every colour channel is gathered alike";
}

TEST(Ex16_2_FinalGather, TheCeilingGivesItsFormFactor) {
  const double F = form_factor_to_ceiling();  // 0.2399
  const Estimate e = gather(ceiling_only([](const vec3&) { return 1.0; }), 8);
  EXPECT_NEAR(e.mean, F, 5 * e.standard_error + 1e-3)
      << "only the ceiling reflects (B - E = 1): H = F(point -> ceiling) = " << F
      << ". Directions must be drawn by the cosine, p = cos / pi, and then each ray counts B - E as it is: no extra "
         "cosine, and not uniform directions (which give the ceiling's share of solid angle, 0.33)";
}

TEST(Ex16_2_FinalGather, EmissionIsTheShadowRaysJob) {
  const gi::RadiosityHandoff h = ceiling_only([](const vec3&) { return 0.0; }, 10.0);
  const Estimate e = gather(h, 4);
  EXPECT_NEAR(e.mean, 0.0, 1e-12) << "the ceiling is a light that reflects nothing (B = E = 10): a gather ray "
                                     "must read B - E = 0 there. The light's own emission reaches x by the shadow "
                                     "rays; gathering it too counts the direct light twice";
}

TEST(Ex16_2_FinalGather, ReadsWhereTheRayLands) {
  // The ceiling is brighter towards x = 1: B - E = 4 x. By symmetry about x = 0.5 the
  // irradiance at the floor's centre is 2 F (the mean of 4x over the ceiling, weighted
  // symmetrically), but only if each ray reads the ceiling where it lands.
  const double F = form_factor_to_ceiling();
  const Estimate e = gather(ceiling_only([](const vec3& c) { return 4 * c.x; }), 8);
  EXPECT_NEAR(e.mean, 2 * F, 5 * e.standard_error + 1e-3)
      << "B - E = 4x on the ceiling gives H = 2 F = " << 2 * F << " at the floor's centre: read the mesh at the "
         "point y the gather ray hits (its element, y), not at x, where the ray started";
}

TEST(Ex16_2_FinalGather, RaysThatLeaveCountAsDark) {
  // Without a ceiling: every wall reflects B - E = 1, the opening nothing.
  const gi::Mesh mesh = lab16::room_mesh(false);
  const gi::RadiosityHandoff h = lab16::room_handoff(
      mesh, [](int, const vec3&) { return constant(1); }, [](int, const vec3&) { return constant(0); },
      [](int, const vec3&) { return constant(0); });
  const double expected = 1 - form_factor_to_ceiling();
  const Estimate e = gather(h, 8);
  EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 1e-3)
      << "with the ceiling open, rays through it find nothing and count 0, but still count: divide by all "
         "strata^2 rays, not by the rays that hit, so H = 1 - F(point -> opening) = "
      << expected;
}
