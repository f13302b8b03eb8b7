// The path tracer against answers known without it: the white furnace's closed form,
// the three strategies against each other, the sky, emission alone; and its contracts:
// the same bytes for any thread count, passes that add up, an honest variance.
#include "gi/pathtrace/path_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <cstring>

#include "gi/pathtrace/path_trace.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/cornell_box.hpp"
#include "support/statistics.hpp"

namespace t = gi::testing;

namespace {

// The mean over pixels and channels of one picture.
double picture_mean(const gi::Image& image) {
  double sum = 0;
  for (const gi::Pixel& p : image.pixels) sum += (double(p.x) + p.y + p.z) / 3;
  return sum / double(image.pixels.size());
}

// The picture's mean radiance, rendered from `seeds` independent seeds: the mean of
// the per-seed means and its standard error.
t::Estimate render_mean(const gi::PathScene& scene, const gi::PathSettings& settings, int size, int spp, int seeds,
                        std::uint64_t first_seed = 1) {
  std::vector<double> means;
  for (int k = 0; k < seeds; ++k) {
    gi::Film film = gi::make_film(size, size, first_seed + k);
    gi::path_trace(film, scene, settings, spp, 0);
    means.push_back(picture_mean(gi::film_mean(film)));
  }
  return t::estimate(means);
}

gi::PathSettings with(gi::Strategy strategy, int max_depth = 64, int roulette_depth = 3) {
  gi::PathSettings s;
  s.strategy = strategy;
  s.max_depth = max_depth;
  s.roulette_depth = roulette_depth;
  return s;
}

const gi::Strategy strategies[] = {gi::Strategy::Bsdf, gi::Strategy::Lights, gi::Strategy::Mis};

}  // namespace

TEST(PathTracer, WhiteFurnaceHasTheClosedForm) {
  // Closed box, rho everywhere, L_e everywhere: with at most D bounces the radiance is
  // L_e (1 + rho + ... + rho^D), every pixel. 20 seeds per case; 5 standard errors of
  // Student's t with 19 degrees of freedom are exceeded by chance about once in 12 000
  // cases, and there are 12 cases here.
  for (const double rho : {0.5, 0.8})
    for (const int depth : {1, 5, 64}) {
      const gi::PathScene furnace = gi::make_path_scene(gi::furnace_scene(rho, 1.5));
      double expected = 0;
      for (int k = 0; k <= depth; ++k) expected += 1.5 * std::pow(rho, k);
      for (const gi::Strategy strategy : {gi::Strategy::Lights, gi::Strategy::Mis}) {
        const t::Estimate e = render_mean(furnace, with(strategy, depth), 8, 16, 20);
        EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 1e-6 * expected)
            << gi::name(strategy) << ", rho " << rho << ", depth " << depth;
      }
      // BSDF sampling alone: every ray meets a wall of radiance L_e and reflectance rho,
      // so the throughput is exactly rho^k until roulette starts (then no noise at all
      // but the float pictures' rounding, 1e-7).
      const t::Estimate b = render_mean(furnace, with(gi::Strategy::Bsdf, depth), 8, 16, 20);
      EXPECT_NEAR(b.mean, expected, 5 * b.standard_error + 1e-6 * expected)
          << "bsdf, rho " << rho << ", depth " << depth;
    }
}

TEST(PathTracer, RussianRouletteDoesNotBias) {
  // The furnace with rho = 0.8 and paths of up to 40 bounces, L = (1 - rho^41) / (1 - rho):
  // roulette from the first bounce, the third, or never. Same false failure rate as
  // above, 3 cases.
  const gi::PathScene furnace = gi::make_path_scene(gi::furnace_scene(0.8, 1.0));
  const double expected = (1 - std::pow(0.8, 41)) / 0.2;
  for (const int roulette : {0, 3, 1000}) {
    const t::Estimate e = render_mean(furnace, with(gi::Strategy::Mis, 40, roulette), 8, 16, 20);
    EXPECT_NEAR(e.mean, expected, 5 * e.standard_error) << "roulette from bounce " << roulette;
  }
}

TEST(PathTracer, TheThreeStrategiesAgree) {
  // Light sampling alone, BSDF sampling alone, and both with MIS estimate the same
  // picture: on the Cornell box (a quad light, all diffuse), with a mirror and glass
  // ball (the specular branch), under an area light and under small sphere lights
  // (lesson 04's and lesson 02's scenes made physical). Welch's difference of two means
  // of 20 seeds each, within 5 standard errors: 12 comparisons, a false failure about
  // once in 10^3 runs of this test.
  for (const char* name : {"cornell", "cornell-spheres", "soft", "spheres"}) {
    const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name(name));
    std::vector<t::Estimate> e;
    for (const gi::Strategy s : strategies) e.push_back(render_mean(scene, with(s), 16, 16, 20, 10 * int(s) + 1));
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const double se = std::hypot(e[a].standard_error, e[b].standard_error);
        EXPECT_NEAR(e[a].mean, e[b].mean, 5 * se)
            << name << ": " << gi::name(strategies[a]) << " against " << gi::name(strategies[b]);
      }
    // and light sampling helps where it should: less spread than BSDF sampling alone
    if (std::string(name) != "cornell-spheres") {
      EXPECT_LT(e[2].standard_error, e[0].standard_error) << name;
    }
  }
}

TEST(PathTracer, TheSkyAloneIsTheBackground) {
  gi::Scene empty;
  empty.background = gi::Color(0.2, 0.4, 0.8);
  const gi::PathScene scene = gi::make_path_scene(empty);
  gi::Film film = gi::make_film(4, 3, 1);
  gi::path_trace(film, scene, {}, 3, 1);
  for (const gi::Pixel& p : gi::film_mean(film).pixels) EXPECT_EQ(p, gi::Pixel(gi::Color(0.2, 0.4, 0.8)));
  for (const gi::Pixel& p : gi::film_variance(film).pixels) EXPECT_EQ(p, gi::Pixel(0.0f));
}

TEST(PathTracer, DepthZeroShowsOnlyWhatEmits) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  gi::Film film = gi::make_film(32, 32, 1);
  gi::path_trace(film, scene, with(gi::Strategy::Mis, 0), 4, 0);
  int lit = 0;
  const gi::Color L = gi::cornell_palette().light_exitance / gi::pi;  // the light's radiance
  for (const gi::Pixel& p : gi::film_mean(film).pixels) {
    // Each pixel is the light's radiance times the share of its rays that hit it.
    EXPECT_NEAR(p.y * L.x, p.x * L.y, 1e-4 * L.x);
    EXPECT_NEAR(p.z * L.x, p.x * L.z, 1e-4 * L.x);
    lit += std::abs(p.x - L.x) < 1e-5 * L.x;
  }
  EXPECT_GT(lit, 0);
}

TEST(PathTracer, SameBytesForAnyThreadCountAndAnySplitIntoPasses) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell-spheres"));
  const auto render = [&](int threads, std::vector<int> passes) {
    gi::Film film = gi::make_film(24, 20, 9);
    for (int spp : passes) gi::path_trace(film, scene, {}, spp, threads);
    return std::make_pair(gi::film_mean(film), gi::film_variance(film));
  };
  const auto one = render(1, {4});
  const auto bytes_equal = [](const gi::Image& a, const gi::Image& b) {
    return a.same_size(b) && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(gi::Pixel)) == 0;
  };
  for (const auto& [threads, passes] :
       std::vector<std::pair<int, std::vector<int>>>{{2, {4}}, {5, {4}}, {3, {1, 3}}, {1, {2, 1, 1}}}) {
    const auto other = render(threads, passes);
    EXPECT_TRUE(bytes_equal(one.first, other.first)) << threads << " threads";
    EXPECT_TRUE(bytes_equal(one.second, other.second)) << threads << " threads";
  }
}

// Stratified and Sobol' numbers are functions of (pixel, sample, dimension): the same
// bytes on 1 and 3 threads, and in one pass or three.
TEST(PathTracer, EverySequenceGivesTheSameBytesOnOneAndThreeThreads) {
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell-spheres"));
  for (const gi::SamplerKind kind : {gi::SamplerKind::Stratified, gi::SamplerKind::Sobol}) {
    const auto render = [&](int threads, std::vector<int> passes) {
      gi::Film film = gi::make_film(24, 20, 9, kind, 4);
      for (int spp : passes) gi::path_trace(film, scene, {}, spp, threads);
      return film;
    };
    const gi::Film one = render(1, {4}), three = render(3, {1, 3});
    EXPECT_EQ(one.sum, three.sum) << gi::sequence_name(kind);
    EXPECT_EQ(one.m2, three.m2) << gi::sequence_name(kind);
    EXPECT_NE(one.sum, render(1, {2}).sum) << "more samples, another picture";
  }
}

TEST(PathTracer, EachPixelsVarianceEstimateMatchesTheSpreadAcrossSeeds) {
  // The film's variance of a pixel's mean (from its own samples) against the variance
  // of that pixel's mean over 40 independent seeds, summed over all pixels: the two
  // agree within 15% (the spread of the across-seed estimate is about sqrt(2 / 39) /
  // sqrt(pixels) ~ 2%, so 15% is a failure only for a wrong estimate).
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  const int size = 12, seeds = 40;
  std::vector<double> sum(size * size * 3, 0.0), sum2(size * size * 3, 0.0);
  double estimated = 0;
  for (int k = 0; k < seeds; ++k) {
    gi::Film film = gi::make_film(size, size, 100 + k);
    gi::path_trace(film, scene, with(gi::Strategy::Lights), 8, 0);
    const gi::Image mean = gi::film_mean(film), variance = gi::film_variance(film);
    for (int i = 0; i < size * size; ++i)
      for (int c = 0; c < 3; ++c) {
        sum[3 * i + c] += mean.pixels[i][c], sum2[3 * i + c] += double(mean.pixels[i][c]) * mean.pixels[i][c];
        estimated += variance.pixels[i][c] / seeds;
      }
  }
  double observed = 0;
  for (std::size_t i = 0; i < sum.size(); ++i) observed += (sum2[i] - sum[i] * sum[i] / seeds) / (seeds - 1);
  EXPECT_NEAR(estimated / observed, 1.0, 0.15);
}

TEST(PathTracer, BadSettingsAreRefused) {
  EXPECT_THROW(gi::check(with(gi::Strategy::Mis, -1)), std::invalid_argument);
  EXPECT_THROW(gi::check(with(gi::Strategy::Mis, 64, -1)), std::invalid_argument);
  EXPECT_THROW(gi::make_film(0, 10, 1), std::invalid_argument);
  EXPECT_THROW(gi::make_film(10, 20000, 1), std::invalid_argument);
  gi::Film film = gi::make_film(2, 2, 1);
  const gi::PathScene scene = gi::make_path_scene(gi::furnace_scene(0.5, 1));
  EXPECT_THROW(gi::path_trace(film, scene, {}, -1, 1), std::invalid_argument);
  EXPECT_THROW(gi::furnace_scene(1.0, 1.0), std::invalid_argument);
  gi::Scene point_lit;
  point_lit.add(gi::PointLight{{0, 1, 0}, gi::Color(1)});
  EXPECT_THROW(gi::make_path_scene(point_lit), std::invalid_argument) << "point lights have no place in it";
  EXPECT_THROW(gi::make_path_scene_by_name("nowhere"), std::invalid_argument);
}

TEST(PathTracer, EveryNamedSceneRenders) {
  for (const std::string& name : gi::path_scene_names()) {
    const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name(name));
    EXPECT_FALSE(scene.lights.lights.empty() && scene.scene().background == gi::Color(0.0)) << name << " is dark";
    gi::Film film = gi::make_film(8, 6, 1);
    gi::path_trace(film, scene, {}, 2, 0);
    EXPECT_EQ(film.discarded, 0) << name;
    EXPECT_GT(picture_mean(gi::film_mean(film)), 0.0) << name;
  }
}

TEST(PathTracer, WhittedLightsBecomeEmittersAsBrightAtTheLookAtPoint) {
  // A point light I_l at distance d lights a diffuse surface k_d I_l (N.L) in lesson 02;
  // its sphere of radius r = 0.02 d has radiance L = I_l d^2 / r^2, which gives
  // (k_d / pi) pi L (r / d)^2 = k_d I_l at that distance.
  const gi::Scene whitted = gi::make_scene("spheres");
  const gi::Scene physical = gi::physical_scene(whitted);
  ASSERT_EQ(physical.spheres.size(), whitted.spheres.size() + whitted.lights.size());
  const gi::Sphere& light = physical.spheres.back();
  const double d = gi::length(whitted.lights[0].position - whitted.camera.look_at);
  EXPECT_NEAR(light.radius, 0.02 * d, 1e-12);
  const gi::Color L = physical.materials[light.material].emission;
  EXPECT_NEAR(L.x * light.radius * light.radius / (d * d), whitted.lights[0].intensity.x, 1e-12);
  EXPECT_TRUE(physical.lights.empty() && physical.area_lights.empty());
  // Lesson 04's area light reuses the quad the camera saw of it.
  const gi::Scene soft = gi::physical_scene(gi::make_scene("soft"));
  int emitting = 0;
  for (const gi::Quad& q : soft.quads) emitting += gi::max_component(soft.materials[q.material].emission) > 0;
  EXPECT_EQ(emitting, 1);
}
