// The BSDFs: sampling against density (chi-square), energy, reciprocity, and the
// specular kinds against lesson 02's optics.
#include "gi/pathtrace/bsdf.hpp"

#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/raytrace/optics.hpp"
#include "support/statistics.hpp"

using gi::vec2;
using gi::vec3;
namespace t = gi::testing;

namespace {

const vec3 n = gi::normalize(vec3(0.3, 1.0, -0.2));  // not along an axis
const gi::Bsdf lambert{gi::BsdfKind::Lambertian, gi::Color(0.8, 0.5, 0.2), 1.0};

vec3 direction(double theta, double phi, const vec3& axis) {
  const vec3 tangent = gi::normalize(gi::cross(axis, vec3(0, 0, 1)));
  const vec3 bitangent = gi::cross(axis, tangent);
  return std::cos(theta) * axis + std::sin(theta) * (std::cos(phi) * tangent + std::sin(phi) * bitangent);
}

}  // namespace

TEST(Bsdf, LambertianSamplesFollowItsDensity) {
  // Both sides of the surface reflect: wo above and below. Two chi-square tests at the
  // Sidak level for a 1% chance of a false failure between them.
  const double significance = t::sidak_significance(0.01, 2);
  gi::Rng rng(1);
  for (const vec3& wo : {direction(0.7, 0.4, n), direction(2.5, 1.0, n)}) {
    std::vector<vec2> points;
    for (int k = 0; k < 100000; ++k) {
      const auto s = gi::sample_bsdf(lambert, n, wo, vec2(rng.uniform(), rng.uniform()), rng.uniform());
      ASSERT_TRUE(s);
      ASSERT_FALSE(s->specular);
      ASSERT_GT(gi::dot(s->wi, n) * gi::dot(wo, n), 0) << "reflected to wo's side";
      ASSERT_NEAR(s->pdf, gi::bsdf_pdf(lambert, n, wo, s->wi), 1e-12);
      // f cos / p = rho for every sample
      ASSERT_NEAR(s->weight.x, 0.8, 1e-12);
      ASSERT_NEAR(s->weight.z, 0.2, 1e-12);
      points.push_back(t::direction_to_z_phi(s->wi));
    }
    // Cells in world (z, phi); the density has a kink along the surface's horizon, which
    // is not a cell border here, so the cells are many and Simpson's grid fine.
    const auto pdf = [&](vec2 zp) { return gi::bsdf_pdf(lambert, n, wo, t::z_phi_to_direction(zp)); };
    const vec2 lo(-1, 0), hi(1, 2 * gi::pi);
    const t::ChiSquare c =
        t::chi_square_test(t::histogram_2d(points, lo, hi, 16, 32), t::expected_2d(pdf, lo, hi, 16, 32, 100000, 16));
    EXPECT_GT(c.p_value, significance) << "chi-square " << c.statistic << ", " << c.degrees_of_freedom << " dof";
  }
}

TEST(Bsdf, LambertianDensityIntegratesToOneAndEnergyToRho) {
  const vec3 wo = direction(1.1, 2.0, n);
  EXPECT_NEAR(t::integral_over_sphere([&](const vec3& wi) { return gi::bsdf_pdf(lambert, n, wo, wi); }), 1.0, 1e-3);
  // The directional albedo int f |cos| dw_i is rho: no more leaves than arrives.
  EXPECT_NEAR(t::integral_over_sphere(
                  [&](const vec3& wi) { return gi::bsdf_f(lambert, n, wo, wi).x * std::abs(gi::dot(n, wi)); }),
              0.8, 1e-3);
}

TEST(Bsdf, LambertianIsReciprocalAndZeroAcrossTheSurface) {
  const vec3 a = direction(0.3, 0.1, n), b = direction(1.2, 2.9, n), below = direction(2.0, 1.0, n);
  EXPECT_EQ(gi::bsdf_f(lambert, n, a, b), gi::bsdf_f(lambert, n, b, a));
  EXPECT_EQ(gi::bsdf_f(lambert, n, a, b), lambert.albedo / gi::pi);
  EXPECT_EQ(gi::bsdf_f(lambert, n, a, below), gi::Color(0.0)) << "light does not pass through";
  EXPECT_EQ(gi::bsdf_pdf(lambert, n, a, below), 0.0);
}

TEST(Bsdf, MirrorReflectsExactly) {
  const gi::Bsdf mirror{gi::BsdfKind::Mirror, gi::Color(0.9), 1.0};
  const vec3 wo = direction(0.8, 1.3, n);
  const auto s = gi::sample_bsdf(mirror, n, wo, vec2(0.3, 0.7), 0.5);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->specular);
  EXPECT_NEAR(gi::length(s->wi + wo - 2 * gi::dot(wo, n) * n), 0.0, 1e-12) << "wi = 2 (wo.n) n - wo";
  EXPECT_EQ(s->weight, gi::Color(0.9));
  EXPECT_EQ(gi::bsdf_f(mirror, n, wo, s->wi), gi::Color(0.0)) << "a delta: no direction picked by anyone else";
  EXPECT_EQ(gi::bsdf_pdf(mirror, n, wo, s->wi), 0.0);
}

TEST(Bsdf, DielectricChoosesByTheExactFresnelFraction) {
  // From outside at 60 degrees: reflected with probability F (lesson 02's Fresnel), the
  // rest refracted by Snell's law. Binomial: 5 standard errors, a false failure about
  // once in 2 million seeds.
  const gi::Bsdf glass{gi::BsdfKind::Dielectric, gi::Color(1.0), 1.5};
  const vec3 wo = direction(gi::pi / 3, 0.5, n);
  const double F = gi::fresnel_dielectric(std::cos(gi::pi / 3), 1.0, 1.5);
  gi::Rng rng(2);
  const int trials = 100000;
  int reflected = 0;
  for (int k = 0; k < trials; ++k) {
    const auto s = gi::sample_bsdf(glass, n, wo, vec2(rng.uniform(), rng.uniform()), rng.uniform());
    ASSERT_TRUE(s && s->specular);
    if (gi::dot(s->wi, n) > 0) {
      ++reflected;
      EXPECT_EQ(s->weight, gi::Color(1.0));
      EXPECT_DOUBLE_EQ(s->pdf, F);
    } else {
      // sin(theta_t) = sin(theta_i) / 1.5, and radiance squeezed by (1 / 1.5)^2 entering.
      EXPECT_NEAR(std::sqrt(1 - gi::dot(s->wi, n) * gi::dot(s->wi, n)), std::sin(gi::pi / 3) / 1.5, 1e-12);
      EXPECT_NEAR(s->weight.x, 1 / 2.25, 1e-12);
      EXPECT_DOUBLE_EQ(s->pdf, 1 - F);
    }
  }
  EXPECT_NEAR(double(reflected) / trials, F, 5 * std::sqrt(F * (1 - F) / trials));
}

TEST(Bsdf, DielectricReflectsTotallyInsideBeyondTheCriticalAngle) {
  const gi::Bsdf glass{gi::BsdfKind::Dielectric, gi::Color(1.0), 1.5};
  const double critical = std::asin(1 / 1.5);
  const vec3 inside = direction(gi::pi - (critical + 0.05), 0.2, n);  // wo below the surface
  for (double u : {0.0, 0.5, 0.999}) {
    const auto s = gi::sample_bsdf(glass, n, inside, vec2(0.5), u);
    ASSERT_TRUE(s);
    EXPECT_LT(gi::dot(s->wi, n), 0) << "stays inside";
    EXPECT_EQ(s->weight, gi::Color(1.0));
  }
  // Just inside the critical angle some light leaves, squeezed the other way: 2.25.
  const vec3 leaving = direction(gi::pi - (critical - 0.05), 0.2, n);
  const auto s = gi::sample_bsdf(glass, n, leaving, vec2(0.5), 0.999);
  ASSERT_TRUE(s);
  EXPECT_GT(gi::dot(s->wi, n), 0);
  EXPECT_NEAR(s->weight.x, 2.25, 1e-12);
}

TEST(Bsdf, MaterialsBecomeTheRightKind) {
  gi::Material m;
  m.diffuse = gi::Color(0.4);
  EXPECT_EQ(gi::bsdf_at(m, vec3(0)).kind, gi::BsdfKind::Lambertian);
  m.mirror = gi::Color(0.7);
  EXPECT_EQ(gi::bsdf_at(m, vec3(0)).kind, gi::BsdfKind::Mirror);
  EXPECT_EQ(gi::bsdf_at(m, vec3(0)).albedo, gi::Color(0.7));
  m.transmission = gi::Color(0.9);
  m.ior = 1.33;
  const gi::Bsdf water = gi::bsdf_at(m, vec3(0));
  EXPECT_EQ(water.kind, gi::BsdfKind::Dielectric);
  EXPECT_EQ(water.ior, 1.33);
  gi::Material checker;
  checker.diffuse = gi::Color(0.1);
  checker.checker_size = 1;
  checker.checker_diffuse = gi::Color(0.9);
  EXPECT_EQ(gi::bsdf_at(checker, vec3(0.5, 0, 0.5)).albedo, gi::Color(0.1));
  EXPECT_EQ(gi::bsdf_at(checker, vec3(1.5, 0, 0.5)).albedo, gi::Color(0.9));
}

TEST(Bsdf, GlossySamplesCarryFCosOverPAndStayAboveTheSurface) {
  // The Phong lobe: each sample's weight is f |cos| / p of its own direction, and its pdf
  // the density bsdf_pdf gives; samples below the surface are refused, not kept.
  const gi::Bsdf glossy{gi::BsdfKind::Glossy, gi::Color(0.8), 1.0, 50};
  const vec3 wo = direction(1.2, 0.4, n);  // 69 degrees: part of the lobe dips below
  gi::Rng rng(3);
  int refused = 0;
  for (int k = 0; k < 20000; ++k) {
    const auto s = gi::sample_bsdf(glossy, n, wo, vec2(rng.uniform(), rng.uniform()), rng.uniform());
    if (!s) {
      ++refused;
      continue;
    }
    ASSERT_FALSE(s->specular);
    ASSERT_GT(gi::dot(s->wi, n), 0);
    ASSERT_NEAR(s->pdf, gi::bsdf_pdf(glossy, n, wo, s->wi), 1e-9 * s->pdf);
    const gi::Color f = gi::bsdf_f(glossy, n, wo, s->wi);
    ASSERT_NEAR(s->weight.x, f.x * gi::dot(n, s->wi) / s->pdf, 1e-9);
  }
  EXPECT_GT(refused, 0) << "a grazing wo's lobe reaches below the surface";
}

TEST(Bsdf, GlossyDensityIntegratesToAtMostOneAndIsReciprocal) {
  const gi::Bsdf glossy{gi::BsdfKind::Glossy, gi::Color(0.8), 1.0, 10};
  const vec3 wo = direction(0.3, 2.0, n), a = direction(0.5, 1.0, n);
  // Near the normal the lobe (width ~20 degrees) stays above the surface: all of it counts.
  EXPECT_NEAR(t::integral_over_sphere([&](const vec3& wi) { return gi::bsdf_pdf(glossy, n, wo, wi); }), 1.0, 2e-2);
  // No more leaves than arrives: int f |cos| dw_i <= k_s.
  EXPECT_LT(t::integral_over_sphere(
                [&](const vec3& wi) { return gi::bsdf_f(glossy, n, wo, wi).x * std::abs(gi::dot(n, wi)); }),
            0.8);
  EXPECT_NEAR(gi::bsdf_f(glossy, n, wo, a).x, gi::bsdf_f(glossy, n, a, wo).x, 1e-12);
  gi::Material plate;
  plate.diffuse = gi::Color(0.0);
  plate.specular = gi::Color(0.8);
  plate.shininess = 10;
  EXPECT_EQ(gi::bsdf_at(plate, vec3(0)).kind, gi::BsdfKind::Glossy) << "nothing but a Phong highlight";
  EXPECT_EQ(gi::bsdf_at(plate, vec3(0)).exponent, 10);
  plate.diffuse = gi::Color(0.1);
  EXPECT_EQ(gi::bsdf_at(plate, vec3(0)).kind, gi::BsdfKind::Lambertian) << "a highlight beside a diffuse part is dropped";
}
