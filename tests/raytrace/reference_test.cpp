// The cache of reference images trusts nothing it has not checked: other settings,
// other code, truncated, damaged, hostile and half-written files are all rendered
// again, and the cache is good again afterwards.
#include "gi/raytrace/reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/files.hpp"
#include "gi/core/hash.hpp"
#include "gi/image/image_io.hpp"
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
  gi::CachedImage get(const std::string& scene_key = "whitted") const {
    return gi::cached_reference(world, settings, seed, threads, scene_key, folder);
  }
  fs::path key_file(const gi::CachedImage& c) const { return fs::path(c.file).replace_extension(".key"); }
};


void overwrite(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

}  // namespace

TEST(ReferenceCache, RendersOnceThenReadsBackTheSameImage) {
  const Cache cache("once");
  const gi::CachedImage first = cache.get();
  EXPECT_FALSE(first.from_cache);
  EXPECT_EQ(first.reason, "no cached image");
  const gi::CachedImage second = cache.get();
  EXPECT_TRUE(second.from_cache) << second.reason;
  EXPECT_EQ(second.file, first.file);
  EXPECT_EQ(second.image.pixels, first.image.pixels);
  EXPECT_EQ(second.image.pixels, gi::render(cache.world, cache.settings, cache.seed, 0).image.pixels);
}

TEST(ReferenceCache, EverySettingCountsExactly) {
  Cache cache("exact");
  const gi::CachedImage base = cache.get("soft_shadow_scene, light size 0.05");
  // Issue 12: light sizes 0.0504 and 0.05 once shared a file.
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
  EXPECT_NE(gi::reference_key(cache.world, cache.settings, cache.seed, "a").find(gi::render_code_fingerprint()), std::string::npos);
  EXPECT_EQ(std::string(gi::render_code_fingerprint()).size(), 64u) << "a SHA-256 in hexadecimal";
}

TEST(ReferenceCache, AFileMadeByOtherCodeIsNotTrusted) {
  const Cache cache("code");
  const gi::CachedImage first = cache.get();
  // What a student's earlier, buggy build left: the same settings, another fingerprint.
  std::string key = gi_test::file_text(cache.key_file(first));
  key.replace(key.find(gi::render_code_fingerprint()), 64, std::string(64, '0'));
  overwrite(cache.key_file(first), key);
  const gi::CachedImage again = cache.get();
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(again.reason, "the cached image was made by other library code");
  EXPECT_EQ(again.file, first.file) << "other code replaces the file rather than adding one";
  EXPECT_TRUE(cache.get().from_cache) << "rewritten, the cache is good again";
}

TEST(ReferenceCache, TruncatedDamagedAndHalfWrittenFilesAreRenderedAgain) {
  const Cache cache("damaged");
  const gi::CachedImage good = cache.get();
  const std::string pfm = gi_test::file_text(good.file), key = gi_test::file_text(cache.key_file(good));
  const struct {
    const char* what;
    std::string pfm, key;
    bool has_pfm, has_key;
    const char* reason;
  } cases[] = {
      {"truncated image", pfm.substr(0, pfm.size() / 2), key, true, true, "wrong size"},
      {"empty image", "", key, true, true, "wrong size"},
      {"one flipped bit", pfm.substr(0, 300) + char(pfm[300] ^ 1) + pfm.substr(301), key, true, true, "checksum"},
      {"killed before the key was written", pfm, "", true, false, "key file is missing"},
      {"key without its image", "", key, false, true, "wrong size"},
      {"truncated key", pfm, key.substr(0, key.find("pfm_fnv1a")), true, true, "damaged"},
      {"empty key", pfm, "", true, true, "other settings"},
      {"key of other settings", pfm, key.substr(0, key.find("seed")) + "seed 7\n" + key.substr(key.find("pfm_")), true,
       true, "other settings"},
      {"hostile key of 1 MB", pfm, key + std::string(1 << 20, 'x'), true, true, "too large"},
      {"big-endian header, same size", "PF\n24 18\n+1\n" + pfm.substr(12), key, true, true, "checksum"},
  };
  for (const auto& c : cases) {
    fs::remove(good.file);
    fs::remove(cache.key_file(good));
    if (c.has_pfm) overwrite(good.file, c.pfm);
    if (c.has_key) overwrite(cache.key_file(good), c.key);
    const gi::CachedImage again = cache.get();
    EXPECT_FALSE(again.from_cache) << c.what;
    EXPECT_NE(again.reason.find(c.reason), std::string::npos) << c.what << ": " << again.reason;
    EXPECT_EQ(again.image.pixels, good.image.pixels) << c.what;
    EXPECT_EQ(gi_test::file_text(good.file), pfm) << c.what << ": the image must be rewritten whole";
    EXPECT_TRUE(cache.get().from_cache) << c.what << ": the cache must be good again";
  }
}

TEST(ReferenceCache, AValidPfmWithAForgedKeyOfAnotherSizeIsRefused) {
  const Cache cache("forged");
  const gi::CachedImage good = cache.get();
  // A 2 x 2 PFM with a key that matches this key and checksums it correctly.
  gi::Image tiny(2, 2, gi::Pixel(7.0f));
  gi::write_pfm(tiny, good.file);
  const std::string bytes = gi_test::file_text(good.file);
  overwrite(cache.key_file(good), gi::reference_key(cache.world, cache.settings, cache.seed, "whitted") + "pfm_bytes " +
                                      std::to_string(bytes.size()) + "\npfm_fnv1a " + gi::hex(gi::fnv1a(bytes)) + "\n");
  const gi::CachedImage again = cache.get();
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(again.image.width, 24);
}
