// Graded tests of exercise 16.2: the final-gather estimate. One point per test.
// Random estimates are tested over 40 seeds against a closed form, within 5 standard
// errors of their mean: a correct gather fails by chance about once in 10^6 runs.
#include <cmath>
#include <string>

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
  // With many rays a gather that weighs each ray by its cosine once more tends to
  // 2 x E[cos] = 2 x 2/3 under cosine-drawn directions.
  std::string slip;
  if (std::abs(H.x - 2.0) > 1e-9) {
    gi::Rng probe_rng(8, 16);
    const double many = gi::final_gather(eye, h, floor_centre, up, 32, probe_rng).x;
    if (std::abs(many - 4.0 / 3.0) < 0.02)
      slip = "with 1024 rays H tends to " + std::to_string(many) + ", 2 x 2/3, where 2/3 is the mean cosine of "
             "cosine-drawn directions: you multiply each ray by its cosine, but the density p = cos / pi already "
             "holds it, so L cos / p = (B - E) / pi * cos / (cos / pi) = B - E, with no cosine left. ";
    else if (std::abs(H.x - 2.0 * gi::pi) < 1e-6)
      slip = "H = 2 pi, pi times too large: B - E is a radiosity, its radiance (B - E) / pi, so with p = cos / pi "
             "each ray counts B - E, not pi (B - E). ";
    else if (H.x > 0.2 * 2.0 && H.x < 0.8 * 2.0)
      slip = "about half the gather rays found nothing (H = " + std::to_string(H.x) +
             "): the cosine-weighted directions are about the z axis until they are turned into the frame of the "
             "point's normal n (Onb(n).to_world); here n is +y, and half of them point into the floor. ";
  }
  EXPECT_NEAR(H.x, 2.0, 1e-9) << slip
                              << "in a room whose walls all reflect B - E = 2 the gathered irradiance is exactly "
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
  // The ceiling is brighter towards x = 1 (B - E = 4 x at element centres, blended
  // between them), and x is off-centre, under the dim side. The expected irradiance is
  // the integral of (B - E)(y) cos cos / (pi r^2) over the ceiling, by a 200 x 200
  // midpoint rule that reads the mesh through your reflected_radiosity_at (16.1).
  const gi::RadiosityHandoff h = ceiling_only([](const vec3& c) { return 4 * c.x; });
  const vec3 x(0.2, 1e-9, 0.5);
  double expected = 0;
  const int m = 200;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const vec3 y((i + 0.5) / m, 1.0, (j + 0.5) / m), d = y - x;
      int element = -1;
      for (int e = 0; e < static_cast<int>(h.mesh.elements.size()); ++e) {
        const auto& c = h.mesh.elements[e].shape;
        if (h.mesh.elements[e].surface != 1) continue;
        const vec3 lo = glm::min(glm::min(c.corners[0], c.corners[1]), glm::min(c.corners[2], c.corners[3]));
        const vec3 hi = glm::max(glm::max(c.corners[0], c.corners[1]), glm::max(c.corners[2], c.corners[3]));
        if (y.x >= lo.x && y.x <= hi.x && y.z >= lo.z && y.z <= hi.z) element = e;
      }
      const double r2 = gi::dot(d, d), cos2 = d.y * d.y / r2;  // cos at x times cos at y
      expected += gi::reflected_radiosity_at(h, element, y).x * cos2 / (gi::pi * r2) / (m * m);
    }
  const Estimate e = gather(h, 8, x);
  EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 1e-3)
      << "with B - E growing across the ceiling, the irradiance under its dim side is " << expected
      << ": read the mesh at the point y the gather ray hits (its element, y), not at x, where the ray started";
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

TEST(Ex16_2_FinalGather, FromTheCeilingTheFloorGivesItsFormFactor) {
  // Gathering on the ceiling (normal -y): only the floor reflects, B - E = 1, so H is
  // the form factor from the ceiling's centre to the floor, as from the floor to the
  // ceiling. Directions about z, or about +y, miss most of the floor.
  const gi::RadiosityHandoff h = lab16::room_handoff(
      lab16::room_mesh(), [](int s, const vec3&) { return constant(s == 0 ? 1 : 0); },
      [](int, const vec3&) { return constant(0); }, [](int, const vec3&) { return constant(0); });
  const double F = form_factor_to_ceiling();
  const Estimate e = gather(h, 8, vec3(0.5, 1 - 1e-9, 0.5), vec3(0, -1, 0));
  EXPECT_NEAR(e.mean, F, 5 * e.standard_error + 1e-3)
      << "from the ceiling's centre the floor gives H = " << F << ", got " << e.mean
      << ": the directions must be turned about the point's own normal n (here -y), e.g. Onb(n).to_world(w)";
}
