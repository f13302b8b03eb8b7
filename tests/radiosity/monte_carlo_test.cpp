// Monte Carlo form factors are unbiased for any ray count. Each test averages many
// independent estimates (random streams 0..M-1 of one seed) and asks that the mean lie
// within 4 standard errors of the exact value: a false failure has probability 6e-5
// per comparison, about 2e-3 for the file's 14 comparisons and the spread checks. Before the fix the rays
// beyond n^2 (n = floor(sqrt(rays))) fell into the first strata again: +1.8% on
// parallel squares at 1000 rays, -3.9% on perpendicular ones, +95% on a small
// receiver along the frame's first tangent -- 6 to 30 standard errors here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gi/core/onb.hpp"
#include "gi/radiosity/form_factors/configuration_factors.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"

using gi::vec3;

namespace {

gi::Polygon quad(vec3 o, vec3 u, vec3 v) { return gi::make_polygon({o, o + u, o + u + v, o + v}); }

struct Sample {
  double mean, standard_error;
};

// M estimates of F from polygons[0] to polygons[1] with `rays` rays each.
Sample sample(const std::vector<gi::Polygon>& polygons, int rays, int estimates) {
  const gi::FormFactorScene scene(polygons);
  gi::FormFactorSettings settings;
  settings.method = gi::FormFactorMethod::MonteCarlo;
  settings.rays = rays;
  double sum = 0, squares = 0;
  for (int stream = 0; stream < estimates; ++stream) {
    const gi::FormFactorRow row = gi::form_factor_row_with_diagnostics(scene, polygons[0], stream, settings);
    EXPECT_DOUBLE_EQ(row.error[1], std::sqrt(row.F[1] * (1 - row.F[1]) / rays)) << "the row's standard error";
    sum += row.F[1], squares += row.F[1] * row.F[1];
  }
  const double mean = sum / estimates, variance = (squares - estimates * mean * mean) / (estimates - 1);
  return {mean, std::sqrt(variance / estimates)};
}

void expect_unbiased(const std::vector<gi::Polygon>& polygons, double exact, int rays, int estimates,
                     const std::string& what) {
  const Sample s = sample(polygons, rays, estimates);
  EXPECT_LE(std::abs(s.mean - exact), 4 * s.standard_error)
      << what << ", " << rays << " rays: mean of " << estimates << " estimates " << s.mean << ", exact " << exact
      << ", standard error " << s.standard_error << " (" << (s.mean - exact) / s.standard_error << " of them)";
  // The binomial standard error, which the rows report, bounds the spread of the
  // stratified estimates (the margin 1.25 is 4 standard errors of the spread's
  // estimate from 150 estimates).
  EXPECT_LE(s.standard_error * std::sqrt(estimates), 1.25 * std::sqrt(exact * (1 - exact) / rays)) << what;
}

const gi::Polygon sender = quad({-0.5, -0.5, 0}, {1, 0, 0}, {0, 1, 0});  // the unit square facing +z

}  // namespace

TEST(MonteCarlo, UnbiasedOnParallelSquaresForAnyRayCount) {
  const std::vector<gi::Polygon> squares = {sender, quad({-0.5, -0.5, 1}, {0, 1, 0}, {1, 0, 0})};
  for (int rays : {999, 1000, 1001, 10200})
    expect_unbiased(squares, gi::ff_parallel_rectangles(1, 1, 1), rays, rays > 5000 ? 150 : 600, "parallel squares");
}

TEST(MonteCarlo, UnbiasedOnPerpendicularSquaresForAnyRayCount) {
  const std::vector<gi::Polygon> squares = {sender, quad({-0.5, -0.5, 0}, {0, 0, 1}, {1, 0, 0})};
  for (int rays : {999, 1000, 1001, 10200})
    expect_unbiased(squares, gi::ff_perpendicular_rectangles(1, 1, 1), rays, rays > 5000 ? 150 : 600,
                    "perpendicular squares");
}

TEST(MonteCarlo, UnbiasedForSmallReceiversAlongTheSamplingFramesAxes) {
  // A 0.1 x 0.1 square 1 from the sender's centre, facing it, straight up and 60
  // degrees off towards each tangent axis of the frame the rays are drawn in. The
  // exact value is the analytic method's (exact to 1e-10 without occlusion).
  const gi::Onb frame(sender.normal);
  const double s = std::sin(std::numbers::pi / 3), c = std::cos(std::numbers::pi / 3);
  const std::vector<std::pair<std::string, vec3>> directions = {
      {"normal", frame.w}, {"+u", c * frame.w + s * frame.u}, {"-u", c * frame.w - s * frame.u},
      {"+v", c * frame.w + s * frame.v}, {"-v", c * frame.w - s * frame.v}};
  for (const auto& [name, d] : directions) {
    const gi::Onb facing(-d);  // the receiver's corners counter-clockwise about -d
    const gi::Polygon receiver = quad(d - 0.05 * facing.u - 0.05 * facing.v, 0.1 * facing.u, 0.1 * facing.v);
    const double exact = gi::form_factor_analytic_adaptive(sender, receiver).value;
    expect_unbiased({sender, receiver}, exact, 1000, 2000, "small receiver towards " + name);
    if (name == "+u") expect_unbiased({sender, receiver}, exact, 10200, 200, "small receiver towards +u");
  }
}
