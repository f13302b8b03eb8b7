// The stored path-traced truths (lessons/references/): the Cornell box kept in the tree
// is the scene's current picture, converged as far as its text says, and is refused in
// one line when damaged or asked for at a size it cannot give.
#include "gi/pathtrace/path_truth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gi/pathtrace/path_scenes.hpp"
#include "support/statistics.hpp"

namespace fs = std::filesystem;
namespace t = gi::testing;

namespace {

const fs::path references = fs::path(GI_SOURCE_DIR) / "lessons/references";

}  // namespace

TEST(StoredTruth, TheCornellBoxInTheTreeIsTheScenesPictureAndConverged) {
  // lessons/references/cornell_256x256: made by 14_make_reference for the Cornell box as
  // radiosity solves it. If the box has changed (reflectances, light, camera), this
  // fails until it is rendered again:
  //   build/release/bin/14_make_reference --scene cornell --width 256 --height 256
  //       --batch-spp 4096 --batches 10 --out lessons/references
  // (hours on two cores; it pools batches, so it can be stopped and run again).
  const gi::PathScene scene = gi::make_path_scene(gi::make_path_scene_by_name("cornell"));
  const gi::Truth truth = gi::stored_truth(references, "cornell", 256, 256);
  EXPECT_GE(truth.spp, 11264);
  EXPECT_EQ(truth.about_value("strategy"), "mis");
  EXPECT_LT(gi::relative_standard_error(truth.standard_error, truth.mean, 1), 0.02) << "per pixel";
  EXPECT_LT(gi::relative_standard_error(truth.standard_error, truth.mean, 8), 0.003) << "per 8x8 block";

  // An independent check that the picture is right: light sampling alone (the truth is
  // MIS), from another seed, at 64 x 64, against the truth averaged to that size.
  // Chi-square of the differences over their standard errors, 4 x 4 blocks and
  // channels: a false failure one time in 1000.
  gi::Film film = gi::make_film(64, 64, 777);
  gi::PathSettings lights;
  lights.strategy = gi::Strategy::Lights;
  gi::path_trace(film, scene, lights, 128, 0);
  const gi::Truth test = gi::downsample(gi::truth_from_film(film, {"", "any", 64, 64}, 777, 0), 4);
  const gi::Truth small = gi::stored_truth(references, "cornell", 16, 16);
  std::vector<double> z2;
  for (std::size_t i = 0; i < small.mean.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = test.mean.pixels[i][c] - small.mean.pixels[i][c];
      const double se2 = double(test.standard_error.pixels[i][c]) * test.standard_error.pixels[i][c] +
                         double(small.standard_error.pixels[i][c]) * small.standard_error.pixels[i][c];
      if (se2 > 0) z2.push_back(d * d / se2);
    }
  double statistic = 0;
  for (double z : z2) statistic += z;
  EXPECT_GT(t::chi_square_p_value(statistic, int(z2.size())), 0.001)
      << "chi-square " << statistic << " for " << z2.size() << " blocks and channels";
}

TEST(StoredTruth, TheBoxWithSpheresIsKeptToo) {
  const gi::Truth truth = gi::stored_truth(references, "cornell-spheres", 64, 64);
  EXPECT_EQ(truth.mean.width, 64);
  EXPECT_GE(truth.spp, 20480);
}

TEST(StoredTruth, ASizeItCannotGiveOrASceneWithoutOneIsRefused) {
  EXPECT_THROW(gi::stored_truth(references, "cornell", 96, 96), std::invalid_argument);
  EXPECT_THROW(gi::stored_truth(references, "cornell", 128, 64), std::invalid_argument);
  EXPECT_THROW(gi::stored_truth(references, "furnace", 16, 16), std::invalid_argument);
  EXPECT_FALSE(gi::stored_truth_side("furnace"));
  // The box's stored truth is not the spheres' box's: another scene's fingerprint.
  try {
    gi::stored_truth_at(references / "cornell_256x256", "cornell-spheres", 256, 256, 256);
    ADD_FAILURE() << "a truth of another scene was used";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("made for another scene"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gi::stored_truth(fs::path(testing::TempDir()) / "nowhere", "cornell", 256, 256), std::runtime_error);
}
