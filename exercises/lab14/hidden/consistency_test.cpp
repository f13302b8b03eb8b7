// Hidden graded tests of lab 14 (the autograder's): the samplers agree with their
// inverses, and next-event estimation scales as the geometry says. One point per test.
#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/core/sampling.hpp"
#include "gi/pathtrace/next_event.hpp"
#include "support/print.hpp"

using gi::vec3;

TEST(Ex14_1_CosineInverse, TheLibrarysInverseGivesBackTheRandomNumbers) {
  // invert_cosine_hemisphere_sample reads u.x = r^2 = x^2 + y^2 and u.y = phi / 2 pi off a
  // direction: Malley's map, and only it, round-trips. A map that is cosine-distributed
  // but puts u somewhere else (r = sqrt(1 - u.x)) still breaks stratified samples.
  gi::Rng rng(1414);
  for (int k = 0; k < 1000; ++k) {
    const gi::vec2 u{rng.uniform(), rng.uniform()};
    const gi::vec2 back = gi::invert_cosine_hemisphere_sample(gi::sample_cosine_hemisphere(u));
    ASSERT_NEAR(back.x, u.x, 1e-9) << "u = (" << u.x << ", " << u.y << "): r = sqrt(u.x) on the disc";
    ASSERT_NEAR(back.y, u.y, 1e-9) << "u = (" << u.x << ", " << u.y << "): phi = 2 pi u.y, from the +x axis";
  }
}

TEST(Ex14_4_NextEventScaling, TwiceAsFarGivesAQuarterOfTheLight) {
  // The same light point moved along the ray to twice the distance, turned the same way:
  // it covers a quarter of the solid angle, so p_light is four times as large and the
  // estimate a quarter; a light drawn twice as densely per unit area gives half.
  const gi::Bsdf white{gi::BsdfKind::Lambertian, gi::Color(0.8), 1.0};
  const vec3 x(0.3, 0, -0.2), n(0, 0, 1), wo(0, 0, 1);
  const vec3 d = gi::normalize(vec3(0.4, -0.3, 1.0)), light_normal = gi::normalize(vec3(-0.2, 0.1, -1.0));
  const gi::LightSample near{x + 1.5 * d, light_normal, gi::Color(5.0), 0.5, 0};
  gi::LightSample far = near, denser = near;
  far.point = x + 3.0 * d;
  denser.pdf_area = 1.0;
  const gi::DirectSample a = gi::next_event_estimate(white, x, n, wo, near);
  const gi::DirectSample b = gi::next_event_estimate(white, x, n, wo, far);
  const gi::DirectSample c = gi::next_event_estimate(white, x, n, wo, denser);
  ASSERT_GT(a.estimate.x, 0.0) << "this light faces x and x faces it: the estimate is positive";
  EXPECT_NEAR(b.p_light / a.p_light, 4.0, 1e-9) << "p_light grows with the distance squared";
  EXPECT_NEAR(b.estimate.x / a.estimate.x, 0.25, 1e-9) << "the light falls off as 1 / distance^2";
  EXPECT_NEAR(c.estimate.x / a.estimate.x, 0.5, 1e-9) << "the estimate divides by the density p_A";
}
