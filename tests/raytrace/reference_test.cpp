// The ray tracer's cached reference (a truth in the lesson's folder, render/truth.hpp):
// rendered once and read back as it was; every setting, the seed and the code count
// exactly; damaged files are rendered again. The truth's own checks are truth_test's.
#include "gi/raytrace/reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "gi/scene/builtin_scenes.hpp"

namespace {

namespace fs = std::filesystem;

struct Cache {
  gi::World world = gi::make_world(gi::make_scene("whitted"));
  gi::RenderSettings settings;
  std::uint64_t seed = 1;
  int threads = 0;
  fs::path folder;
  explicit Cache(const std::string& name) : folder(fs::path(testing::TempDir()) / "gi_reference_test" / name) {
    fs::remove_all(folder);
    settings.width = 24;
    settings.height = 18;
    settings.trace.max_depth = 2;
  }
  gi::CachedTruth get(const std::string& scene_key = "whitted") const {
    return gi::cached_reference(world, settings, seed, threads, scene_key, folder);
  }
};

}  // namespace

TEST(ReferenceCache, RendersOnceThenReadsBackTheSameImage) {
  const Cache cache("once");
  const gi::CachedTruth first = cache.get();
  EXPECT_FALSE(first.from_cache);
  EXPECT_EQ(first.reason, "none kept");
  const gi::CachedTruth second = cache.get();
  EXPECT_TRUE(second.from_cache) << second.reason;
  EXPECT_EQ(second.stem, first.stem);
  EXPECT_EQ(second.truth.mean.pixels, first.truth.mean.pixels);
  EXPECT_EQ(second.truth.mean.pixels, gi::render(cache.world, cache.settings, cache.seed, 0).image.pixels);
}

TEST(ReferenceCache, EverySettingCountsExactly) {
  Cache cache("exact");
  cache.get("soft_shadow_scene, light size 0.05");
  // Light sizes 0.0504 and 0.05 are two scenes, and two files.
  EXPECT_FALSE(cache.get("soft_shadow_scene, light size 0.0504").from_cache);
  const double step = std::nextafter(0.0, 1.0);
  cache.settings.trace.min_contribution += step;  // the smallest change a double can make
  EXPECT_FALSE(cache.get("soft_shadow_scene, light size 0.05").from_cache);
  cache.settings.trace.min_contribution = 0;
  cache.seed = 2;
  EXPECT_FALSE(cache.get("soft_shadow_scene, light size 0.05").from_cache);
  cache.seed = 1;
  cache.threads = 3;  // the image does not depend on it
  EXPECT_TRUE(cache.get("soft_shadow_scene, light size 0.05").from_cache);
  EXPECT_EQ(gi::reference_key(cache.world, cache.settings, cache.seed, "a").code, gi::render_code_fingerprint());
  EXPECT_EQ(std::string(gi::render_code_fingerprint()).size(), 64u) << "a SHA-256 in hexadecimal";
}

TEST(ReferenceCache, AFileMadeByOtherCodeOrDamagedIsRenderedAgain) {
  const Cache cache("code");
  const gi::CachedTruth first = cache.get();
  // What a student's earlier, buggy build left: the same settings, another code.
  gi::Truth old = first.truth;
  old.code = std::string(64, '0');
  gi::save_truth(old, first.stem);
  const gi::CachedTruth again = cache.get();
  EXPECT_FALSE(again.from_cache);
  EXPECT_NE(again.reason.find("made by other library code"), std::string::npos) << again.reason;
  EXPECT_EQ(again.stem, first.stem) << "other code replaces the files rather than adding some";
  EXPECT_TRUE(cache.get().from_cache) << "rewritten, the cache is good again";
  fs::resize_file(first.stem.string() + ".pfm", 40);
  const gi::CachedTruth truncated = cache.get();
  EXPECT_FALSE(truncated.from_cache);
  EXPECT_EQ(truncated.truth.mean.pixels, first.truth.mean.pixels);
  EXPECT_TRUE(cache.get().from_cache);
}
