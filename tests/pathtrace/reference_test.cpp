// References on disk: what is written is read back, what is stale or broken is refused,
// batches pool exactly; and the Cornell box reference kept in the tree is the scene's
// current picture, converged as far as its text file says.
#include "gi/pathtrace/reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "gi/core/platform/process.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "support/statistics.hpp"

namespace fs = std::filesystem;
namespace t = gi::testing;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gi_reference_test_" + std::to_string(gi::platform::current_process_id()));
  fs::create_directories(dir);
  return dir / name;
}

gi::PathReference small_reference(const std::string& fingerprint, std::uint64_t seed = 1) {
  const gi::PathScene scene = gi::make_path_scene(gi::furnace_scene(0.5, 1.0));
  gi::Film film = gi::make_film(4, 2, seed);
  gi::render_pass(film, scene, {}, 8, 1);
  return gi::reference_from_film(film, "furnace", fingerprint, seed, {}, 0.5);
}

gi::PathReference one_pixel(const std::vector<double>& samples) {
  // A reference of one grey pixel with these samples' mean and standard error.
  const double n = double(samples.size());
  double mean = 0, m2 = 0;
  for (double x : samples) mean += x / n;
  for (double x : samples) m2 += (x - mean) * (x - mean);
  gi::PathReference r;
  r.fingerprint = "f";
  r.mean = gi::Image(1, 1, gi::Pixel(float(mean)));
  r.standard_error = gi::Image(1, 1, gi::Pixel(float(std::sqrt(m2 / (n - 1) / n))));
  r.spp = static_cast<long long>(n);
  return r;
}

}  // namespace

TEST(Reference, WhatIsSavedIsLoaded) {
  const gi::PathReference r = small_reference("abc");
  const fs::path stem = scratch("round_trip");
  gi::save_reference(r, stem);
  std::string why;
  const auto back = gi::load_reference(stem, "abc", &why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->spp, 8);
  EXPECT_EQ(back->scene, "furnace");
  EXPECT_EQ(back->batches, 1);
  EXPECT_EQ(back->settings.max_depth, 64);
  EXPECT_EQ(back->mean.pixels, r.mean.pixels);
  EXPECT_EQ(back->standard_error.pixels, r.standard_error.pixels);
}

TEST(Reference, StaleOrBrokenFilesAreRefused) {
  const fs::path stem = scratch("broken");
  gi::save_reference(small_reference("abc"), stem);
  std::string why;
  EXPECT_FALSE(gi::load_reference(stem, "other", &why));
  EXPECT_NE(why.find("another scene"), std::string::npos) << why;
  // A picture cut short.
  fs::resize_file(fs::path(stem.string() + "_stderr.pfm"), 40);
  EXPECT_FALSE(gi::load_reference(stem, "abc", &why));
  EXPECT_NE(why.find("_stderr.pfm"), std::string::npos) << why;
  // A text file with nonsense in it.
  gi::save_reference(small_reference("abc"), stem);
  std::ofstream(stem.string() + ".txt") << "scene x\nfingerprint abc\nwidth many\n";
  EXPECT_FALSE(gi::load_reference(stem, "abc", &why));
  std::ofstream(stem.string() + ".txt") << "\x01\x02 garbage\n";
  EXPECT_FALSE(gi::load_reference(stem, "abc", &why));
  // A pixel that is not a number, or negative: refused, not turned into an error figure.
  for (const float bad : {std::nanf(""), -1.0f}) {
    gi::PathReference r = small_reference("abc");
    r.mean.at(1, 0) = gi::Pixel(bad);
    gi::save_reference(r, stem);
    EXPECT_FALSE(gi::load_reference(stem, "abc", &why)) << bad;
    EXPECT_NE(why.find("negative or not a number"), std::string::npos) << why;
  }
  // A text file a hostile hand made huge is refused unread.
  gi::save_reference(small_reference("abc"), stem);
  std::ofstream(stem.string() + ".txt", std::ios::app) << "# " << std::string(1 << 17, 'x') << '\n';
  EXPECT_FALSE(gi::load_reference(stem, "abc", &why));
  EXPECT_NE(why.find("too large"), std::string::npos) << why;
  // No text file: nothing is trusted, whatever pictures lie there.
  fs::remove(stem.string() + ".txt");
  EXPECT_FALSE(gi::load_reference(stem, "abc", &why));
  EXPECT_FALSE(gi::load_reference(scratch("nothing_here"), "abc"));
}

TEST(Reference, BatchesPoolLikeOneSetOfSamples) {
  // {1, 3} and {5, 7, 9} pooled are {1, 3, 5, 7, 9}: mean 5, s^2 = 10, se^2 = 10 / 5.
  const gi::PathReference pooled = gi::combine(one_pixel({1, 3}), one_pixel({5, 7, 9}));
  EXPECT_EQ(pooled.spp, 5);
  EXPECT_EQ(pooled.batches, 2);
  EXPECT_NEAR(pooled.mean.pixels[0].x, 5.0, 1e-6);
  EXPECT_NEAR(pooled.standard_error.pixels[0].x, std::sqrt(2.0), 1e-6);
  gi::PathReference other = one_pixel({1, 2});
  other.fingerprint = "g";
  EXPECT_THROW(gi::combine(one_pixel({1, 3}), other), std::invalid_argument);
}

TEST(Reference, RelativeErrorsAndDownsampling) {
  gi::Image reference(4, 2, gi::Pixel(2.0f)), test(4, 2, gi::Pixel(2.0f));
  test.at(0, 0) = gi::Pixel(3.0f);  // +50% in one pixel of eight
  EXPECT_NEAR(gi::relative_rms_error(test, reference), std::sqrt(0.25 / 8), 1e-7);
  EXPECT_NEAR(gi::relative_rms_error(test, reference, 2), std::sqrt(0.125 * 0.125 / 2), 1e-7);
  EXPECT_THROW(gi::relative_rms_error(test, reference, 3), std::invalid_argument);
  gi::PathReference r;
  r.mean = reference;
  r.mean.at(1, 1) = gi::Pixel(6.0f);
  r.standard_error = gi::Image(4, 2, gi::Pixel(0.2f));
  EXPECT_NEAR(gi::relative_standard_error(r, 1), std::sqrt((7 * 0.01 + 0.2 * 0.2 / 36) / 8), 1e-6);
  const gi::PathReference half = gi::downsample(r, 2);
  ASSERT_EQ(half.mean.width, 2);
  EXPECT_NEAR(half.mean.at(0, 0).x, (2 + 2 + 2 + 6) / 4.0, 1e-6);
  EXPECT_NEAR(half.standard_error.at(0, 0).x, std::sqrt(4 * 0.04) / 4, 1e-6) << "independent errors: sqrt(sum) / 4";
}

TEST(Reference, TheCornellBoxReferenceInTheTreeIsTheScenesPictureAndConverged) {
  // lessons/references/cornell_256x256: made by 14_make_reference for the Cornell box as
  // radiosity solves it. If the box has changed (reflectances, light, camera), this
  // fails until it is rendered again:
  //   build/release/bin/14_make_reference --scene cornell --width 256 --height 256
  //       --batch-spp 4096 --batches 10 --out lessons/references
  // (hours on two cores; it pools batches, so it can be stopped and run again).
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  const std::string fingerprint = gi::reference_fingerprint(scene, {}, 256, 256);
  std::string why;
  const auto reference =
      gi::load_reference(fs::path(GI_SOURCE_DIR) / "lessons/references/cornell_256x256", fingerprint, &why);
  ASSERT_TRUE(reference) << why << "\nrender it again (see this test's comment)";
  EXPECT_GE(reference->spp, 11264);
  EXPECT_LT(gi::relative_standard_error(*reference, 1), 0.02) << "per pixel";
  EXPECT_LT(gi::relative_standard_error(*reference, 8), 0.003) << "per 8x8 block";

  // An independent check that the picture is right: light sampling alone (the reference
  // is MIS), from another seed, at 64 x 64, against the reference averaged to that size.
  // Chi-square of the differences over their standard errors, 4 x 4 blocks and
  // channels: a false failure one time in 1000.
  gi::Film film = gi::make_film(64, 64, 777);
  gi::PathSettings lights;
  lights.strategy = gi::Strategy::Lights;
  gi::render_pass(film, scene, lights, 128, 0);
  const gi::PathReference test = gi::downsample(gi::reference_from_film(film, "cornell", "", 777, lights, 0), 4);
  const gi::PathReference truth = gi::downsample(*reference, 16);
  std::vector<double> z2, ones;
  for (std::size_t i = 0; i < truth.mean.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = test.mean.pixels[i][c] - truth.mean.pixels[i][c];
      const double se2 = double(test.standard_error.pixels[i][c]) * test.standard_error.pixels[i][c] +
                         double(truth.standard_error.pixels[i][c]) * truth.standard_error.pixels[i][c];
      if (se2 > 0) z2.push_back(d * d / se2);
    }
  double statistic = 0;
  for (double z : z2) statistic += z;
  EXPECT_GT(t::chi_square_p_value(statistic, int(z2.size())), 0.001)
      << "chi-square " << statistic << " for " << z2.size() << " blocks and channels";
}
