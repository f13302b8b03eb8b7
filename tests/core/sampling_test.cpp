// Every sampler of gi/core/sampling.hpp against its density: a chi-square test of
// the samples against the density integrated over the same cells, the density's
// integral (1), the domain, and the inverse map where there is one.
#include "gi/core/sampling.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "gi/core/rng.hpp"
#include "support/statistics.hpp"

using gi::vec2;
using gi::vec3;
namespace t = gi::testing;

namespace {

// Seven chi-square tests below; each passes at the Sidak level that keeps the chance of
// any false failure in this file at 1% (for a correct sampler and a random seed; the
// seeds here are fixed, so the outcome is too).
constexpr int chi_square_tests = 7;
const double significance = t::sidak_significance(0.01, chi_square_tests);
constexpr int samples = 200000;

std::vector<vec2> uniforms(std::uint64_t stream, int n = samples) {
  gi::Rng rng(11, stream);
  std::vector<vec2> u(n);
  for (vec2& x : u) x = vec2(rng.uniform(), rng.uniform());
  return u;
}

// Chi-square of directions against a density per steradian, on 10 x 20 cells of
// (cos theta, phi): the horizon z = 0 is a cell border, where the hemisphere's
// densities have their kink.
t::ChiSquare directions_test(const std::vector<vec3>& w, const std::function<double(const vec3&)>& pdf) {
  std::vector<vec2> points;
  for (const vec3& d : w) points.push_back(t::direction_to_z_phi(d));
  const vec2 lo(-1, 0), hi(1, 2 * gi::pi);
  return t::chi_square_test(
      t::histogram_2d(points, lo, hi, 10, 20),
      t::expected_2d([&](vec2 zp) { return pdf(t::z_phi_to_direction(zp)); }, lo, hi, 10, 20, double(w.size())));
}

void expect_unit(const vec3& w) { ASSERT_NEAR(gi::length(w), 1.0, 1e-12); }

void expect_round_trip(vec2 u, vec2 back) {
  EXPECT_NEAR(back.x, u.x, 1e-9);
  EXPECT_NEAR(back.y, u.y, 1e-9);
}

}  // namespace

TEST(Sampling, UniformHemisphere) {
  std::vector<vec3> w;
  for (vec2 u : uniforms(1)) {
    w.push_back(gi::sample_uniform_hemisphere(u));
    expect_unit(w.back());
    ASSERT_GE(w.back().z, 0.0);
    if (w.size() < 1000) expect_round_trip(u, gi::invert_uniform_hemisphere_sample(w.back()));
  }
  const auto pdf = [](const vec3& d) { return d.z >= 0 ? gi::uniform_hemisphere_pdf() : 0.0; };
  EXPECT_GT(directions_test(w, pdf).p_value, significance);
  EXPECT_NEAR(t::integral_over_sphere(pdf), 1.0, 1e-3);
}

TEST(Sampling, CosineHemisphere) {
  std::vector<vec3> w;
  for (vec2 u : uniforms(2)) {
    w.push_back(gi::sample_cosine_hemisphere(u));
    expect_unit(w.back());
    ASSERT_GE(w.back().z, 0.0);
    if (w.size() < 1000) expect_round_trip(u, gi::invert_cosine_hemisphere_sample(w.back()));
  }
  const auto pdf = [](const vec3& d) { return gi::cosine_hemisphere_pdf(d.z); };
  const t::ChiSquare c = directions_test(w, pdf);
  EXPECT_GT(c.p_value, significance) << "chi-square " << c.statistic << " with " << c.degrees_of_freedom << " dof";
  EXPECT_NEAR(t::integral_over_sphere(pdf), 1.0, 1e-3);
  EXPECT_EQ(gi::cosine_hemisphere_pdf(-0.3), 0.0);
  EXPECT_DOUBLE_EQ(gi::cosine_hemisphere_pdf(1.0), 1 / gi::pi);
}

TEST(Sampling, UniformSphere) {
  std::vector<vec3> w;
  for (vec2 u : uniforms(3)) {
    w.push_back(gi::sample_uniform_sphere(u));
    expect_unit(w.back());
    if (w.size() < 1000) expect_round_trip(u, gi::invert_uniform_sphere_sample(w.back()));
  }
  const auto pdf = [](const vec3&) { return gi::uniform_sphere_pdf(); };
  EXPECT_GT(directions_test(w, pdf).p_value, significance);
  EXPECT_NEAR(t::integral_over_sphere(pdf), 1.0, 1e-3);
}

TEST(Sampling, UniformCone) {
  // cos_max = 0.2 is a cell border of the 10 z-bins, where the density jumps.
  const double cos_max = 0.2;
  std::vector<vec3> w;
  for (vec2 u : uniforms(4)) {
    w.push_back(gi::sample_uniform_cone(u, cos_max));
    expect_unit(w.back());
    ASSERT_GE(w.back().z, cos_max - 1e-12);
    if (w.size() < 1000) expect_round_trip(u, gi::invert_uniform_cone_sample(w.back(), cos_max));
  }
  const auto pdf = [&](const vec3& d) { return d.z >= cos_max ? gi::uniform_cone_pdf(cos_max) : 0.0; };
  EXPECT_GT(directions_test(w, pdf).p_value, significance);
  EXPECT_NEAR(t::integral_over_sphere(pdf), 1.0, 2e-3);
}

TEST(Sampling, PhongLobe) {
  // n = 10: a lobe wide enough for the 10 x 20 cells to resolve (half its density
  // within 21 degrees of +z).
  const double n = 10;
  std::vector<vec3> w;
  for (vec2 u : uniforms(7)) {
    w.push_back(gi::sample_phong_lobe(u, n));
    expect_unit(w.back());
    ASSERT_GE(w.back().z, 0.0);
    if (w.size() < 1000) expect_round_trip(u, gi::invert_phong_lobe_sample(w.back(), n));
  }
  const auto pdf = [&](const vec3& d) { return gi::phong_lobe_pdf(d.z, n); };
  const t::ChiSquare c = directions_test(w, pdf);
  EXPECT_GT(c.p_value, significance) << "chi-square " << c.statistic << " with " << c.degrees_of_freedom << " dof";
  EXPECT_NEAR(t::integral_over_sphere(pdf), 1.0, 2e-3);
  EXPECT_EQ(gi::phong_lobe_pdf(-0.3, n), 0.0);
  EXPECT_DOUBLE_EQ(gi::phong_lobe_pdf(1.0, n), (n + 1) / (2 * gi::pi));
}

TEST(Sampling, UniformTriangle) {
  // Barycentric (b1, b2) on 20 x 20 cells of the unit square: the triangle b1 + b2 <= 1
  // cuts the cells on the diagonal exactly in half, and Simpson's rule on those cells
  // sees the density's step only along their diagonal, so the density is integrated
  // exactly: 2 per unit area of (b1, b2) inside, 0 outside.
  const std::vector<vec2> u = uniforms(5);
  std::vector<vec2> b12;
  for (vec2 x : u) {
    const vec3 b = gi::sample_uniform_triangle(x);
    ASSERT_GE(std::min({b.x, b.y, b.z}), 0.0);
    ASSERT_NEAR(b.x + b.y + b.z, 1.0, 1e-12);
    b12.push_back({b.y, b.z});
    if (b12.size() < 1000) expect_round_trip(x, gi::invert_uniform_triangle_sample(b));
  }
  const int n = 20;
  std::vector<double> expected(n * n + 1, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      expected[j * n + i] = i + j < n - 1 ? 2.0 / (n * n) : i + j == n - 1 ? 1.0 / (n * n) : 0;
  for (double& e : expected) e *= samples;
  EXPECT_GT(t::chi_square_test(t::histogram_2d(b12, {0, 0}, {1, 1}, n, n), expected).p_value, significance);
  // The density in area measure: 1 / A, whose integral over the triangle is 1.
  EXPECT_DOUBLE_EQ(gi::uniform_triangle_pdf(0.25) * 0.25, 1.0);
}

TEST(Sampling, DiscreteDistributionFollowsItsWeights) {
  const std::vector<double> weights = {1, 0, 3, 0.5, 5.5};
  const gi::DiscreteDistribution d = gi::make_discrete_distribution(weights);
  std::vector<double> observed(weights.size(), 0), expected;
  gi::Rng rng(6);
  for (int k = 0; k < samples; ++k) ++observed[gi::sample_discrete(d, rng.uniform())];
  double total = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    expected.push_back(samples * gi::discrete_pdf(d, int(i)));
    total += gi::discrete_pdf(d, int(i));
    EXPECT_DOUBLE_EQ(gi::discrete_pdf(d, int(i)), weights[i] / 10.0);
  }
  EXPECT_NEAR(total, 1.0, 1e-15);
  EXPECT_EQ(observed[1], 0) << "a weight of 0 is never chosen";
  EXPECT_GT(t::chi_square_test(observed, expected).p_value, significance);
  EXPECT_EQ(gi::sample_discrete(d, 0.0), 0);
  EXPECT_EQ(gi::sample_discrete(d, std::nextafter(1.0, 0.0)), 4);
  EXPECT_THROW(gi::make_discrete_distribution({}), std::invalid_argument);
  EXPECT_THROW(gi::make_discrete_distribution({0, 0}), std::invalid_argument);
  EXPECT_THROW(gi::make_discrete_distribution({1, -1}), std::invalid_argument);
  EXPECT_THROW(gi::make_discrete_distribution({1, std::nan("")}), std::invalid_argument);
}

TEST(Sampling, AreaToSolidAngleGivesTheSolidAngleOfASquare) {
  // Points uniform over a square of side a at distance d, facing the origin: the mean of
  // 1 / p_w = A cos(theta_y) / r^2 is the square's solid angle, in closed form
  //   Omega = 4 asin(a^2 / (a^2 + 4 d^2)).
  // 5 standard errors: a false failure about once in 2 million seeds.
  EXPECT_DOUBLE_EQ(gi::area_to_solid_angle(0.5, 4.0, -0.25), 8.0);
  const double a = 2, d = 1.5, area = a * a;
  const double omega = 4 * std::asin(a * a / (a * a + 4 * d * d));
  double sum = 0, sum2 = 0;
  for (vec2 u : uniforms(7)) {
    const vec3 y((u.x - 0.5) * a, (u.y - 0.5) * a, d), normal(0, 0, -1);
    const double r2 = gi::dot(y, y), cos_y = gi::dot(normal, -y) / std::sqrt(r2);
    const double estimate = 1 / gi::area_to_solid_angle(1 / area, r2, cos_y);
    sum += estimate, sum2 += estimate * estimate;
  }
  const double mean = sum / samples, se = std::sqrt((sum2 / samples - mean * mean) / samples);
  EXPECT_NEAR(mean, omega, 5 * se);
}

TEST(Sampling, PowerHeuristicWeightsAddUpToOne) {
  EXPECT_DOUBLE_EQ(gi::power_heuristic(1, 3.0, 1, 1.0), 0.9);
  EXPECT_DOUBLE_EQ(gi::power_heuristic(1, 1.0, 1, 3.0), 0.1);
  EXPECT_DOUBLE_EQ(gi::power_heuristic(2, 1.0, 1, 1.0), 0.8);
  EXPECT_DOUBLE_EQ(gi::power_heuristic(1, 2.0, 1, 0.0), 1.0);
  for (double p : {1e-8, 0.3, 7.0, 1e6})
    EXPECT_NEAR(gi::power_heuristic(1, p, 1, 0.7) + gi::power_heuristic(1, 0.7, 1, p), 1.0, 1e-15);
  EXPECT_EQ(gi::power_heuristic(1, 0.0, 1, 0.0), 0.0) << "0 / 0 is not a weight";
  EXPECT_EQ(gi::power_heuristic(1, INFINITY, 1, 1.0), 0.0) << "inf / inf is not a weight";
  EXPECT_EQ(gi::power_heuristic(1, std::nan(""), 1, 1.0), 0.0);
}

TEST(Sampling, ChiSquareHelperKnowsItsTablesAndCatchesAWrongDensity) {
  // Critical values from the tables: P(chi2_k >= x).
  EXPECT_NEAR(t::chi_square_p_value(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(t::chi_square_p_value(27.88, 9), 0.001, 1e-5);
  EXPECT_NEAR(t::chi_square_p_value(148.2, 99), 0.001, 2e-5);
  EXPECT_NEAR(t::chi_square_p_value(1e3, 1000), 0.4941, 1e-3);
  // Uniform samples tested against the cosine density must fail, by far.
  std::vector<vec3> w;
  for (vec2 u : uniforms(8, 20000)) w.push_back(gi::sample_uniform_hemisphere(u));
  EXPECT_LT(directions_test(w, [](const vec3& d) { return gi::cosine_hemisphere_pdf(d.z); }).p_value, 1e-10);
}
