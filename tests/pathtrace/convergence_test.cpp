// The Monte Carlo error law e^2 = v / N + r^2 (convergence.hpp): the fit and the
// prediction on their own, and the law on the real path tracer against the stored
// Cornell box reference.
#include "gi/pathtrace/convergence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace {

TEST(MonteCarloErrorLaw, FitAndPredictionInvertEachOther) {
  std::vector<gi::ErrorAtSamples> points;
  for (double spp = 1; spp <= 64; spp *= 2) points.push_back({spp, std::sqrt(0.02 / spp + 1e-6)});
  const double v = gi::monte_carlo_variance(points, 1e-3);
  EXPECT_NEAR(v, 0.02, 1e-12);
  EXPECT_NEAR(*gi::samples_for_error(v, std::sqrt(0.02 / 500 + 1e-6), 1e-3), 500, 1e-6);
  EXPECT_FALSE(gi::samples_for_error(v, 1e-3, 1e-3));
}

TEST(MonteCarloErrorLaw, RefusesMeaninglessInput) {
  EXPECT_THROW(gi::monte_carlo_variance({}, 0), std::invalid_argument);
  EXPECT_THROW(gi::monte_carlo_variance({{0.5, 0.1}}, 0), std::invalid_argument);
  EXPECT_THROW(gi::monte_carlo_variance({{4, -0.1}}, 0), std::invalid_argument);
  EXPECT_THROW(gi::monte_carlo_variance({{4, NAN}}, 0), std::invalid_argument);
  EXPECT_THROW(gi::monte_carlo_variance({{1, INFINITY}}, 0), std::invalid_argument);
  EXPECT_THROW(gi::monte_carlo_variance({{1, 0.1}}, -1e-3), std::invalid_argument);
  EXPECT_THROW(gi::samples_for_error(-1, 0.1, 0), std::invalid_argument);
  EXPECT_THROW(gi::samples_for_error(INFINITY, 0.1, 0), std::invalid_argument);
  EXPECT_THROW(gi::samples_for_error(0.03, NAN, 0), std::invalid_argument);
  EXPECT_THROW(gi::samples_for_error(0.03, 0.1, -0.01), std::invalid_argument);
}

TEST(MonteCarloErrorLaw, HoldsForThePathTracerOnTheCornellBox) {
  // The box at 32 x 32 against the stored reference averaged down 8 x, scored per pixel
  // over the interior. For each of 12 seeds: v fitted from the pictures at 1, 2 and 4
  // spp, and v measured at 16 spp alone, 16 (e_16^2 - r^2). The law says both estimate
  // the same v; their paired differences must average 0 within 5 standard errors
  // (a false failure about once in 10^6). A law in e instead of e^2, or r^2 left out,
  // would put them 50% and more apart.
  const gi::RadiosityScene box = gi::cornell_box();
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  const gi::Truth truth =
      gi::stored_truth(std::filesystem::path(GI_SOURCE_DIR) / "lessons/references", "cornell", 32, 32);
  const gi::BlockMask mask = gi::interior_blocks(box.surfaces, box.camera, 32, 32, 1);
  const double r = gi::reference_noise(truth.standard_error, truth.mean, mask).relative_rms;
  const int seeds = 12;
  std::vector<double> differences, fitted;
  for (int seed = 0; seed < seeds; ++seed) {
    gi::Film film = gi::make_film(32, 32, 500 + seed);
    std::vector<gi::ErrorAtSamples> points;
    for (int spp = 1; spp <= 4; spp *= 2) {
      gi::path_trace(film, scene, {}, spp - static_cast<int>(film.samples), 0);
      points.push_back({double(spp), gi::picture_error(gi::film_mean(film), truth.mean, mask).relative_rms});
    }
    const double v = gi::monte_carlo_variance(points, r);
    gi::path_trace(film, scene, {}, 12, 0);
    const double e16 = gi::picture_error(gi::film_mean(film), truth.mean, mask).relative_rms;
    differences.push_back(v - 16 * (e16 * e16 - r * r));
    fitted.push_back(v);
  }
  double mean = 0, spread = 0, v_mean = 0;
  for (std::size_t k = 0; k < differences.size(); ++k) mean += differences[k] / seeds, v_mean += fitted[k] / seeds;
  for (double d : differences) spread += (d - mean) * (d - mean) / (seeds - 1);
  EXPECT_LT(std::abs(mean), 5 * std::sqrt(spread / seeds))
      << "fitted v " << v_mean << ", the 16-spp pictures' v differs by " << mean << " on average";
  EXPECT_GT(v_mean, 0.0);
}

}  // namespace
