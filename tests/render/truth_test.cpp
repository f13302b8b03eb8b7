// Truths on disk trust nothing they have not checked: what is written is read back; a
// truth of another scene, size or code, or one truncated, damaged, forged or implausible
// is refused in one line; batches pool exactly; the cache renders again what it refuses.
#include "gi/render/truth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "../support/files.hpp"
#include "gi/image/image_io.hpp"
#include "gi/render/render_pass.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / "gi_truth_test";
  fs::create_directories(dir);
  return dir / name;
}

const gi::TruthKey key{"abc", "code-1", 6, 4};

// A small noisy picture: every pixel the mean of 8 uniform numbers in [1, 2).
gi::Film noisy_film(std::uint64_t seed = 1) {
  gi::Film film = gi::make_film(6, 4, seed);
  const auto noisy = [](const gi::Ray&, gi::PixelSample& s) { return gi::Color(1 + s.rng.uniform()); };
  for (int k = 0; k < 8; ++k) gi::render_pass(film, {}, {}, noisy, 1);
  return film;
}

gi::Truth small_truth() { return gi::truth_from_film(noisy_film(), key, 1, 0.5, {{"scene", "a box"}}); }

gi::Truth one_pixel(const std::vector<double>& samples) {
  // A truth of one grey pixel with these samples' mean and standard error.
  const double n = double(samples.size());
  double mean = 0, m2 = 0;
  for (double x : samples) mean += x / n;
  for (double x : samples) m2 += (x - mean) * (x - mean);
  gi::Truth t;
  t.fingerprint = "f";
  t.mean = gi::Image(1, 1, gi::Pixel(float(mean)));
  t.standard_error = gi::Image(1, 1, gi::Pixel(float(std::sqrt(m2 / (n - 1) / n))));
  t.spp = static_cast<long long>(n);
  return t;
}

void overwrite(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

}  // namespace

TEST(Truth, WhatIsSavedIsLoaded) {
  const gi::Truth t = small_truth();
  const fs::path stem = scratch("round_trip");
  gi::save_truth(t, stem);
  std::string why;
  const auto back = gi::load_truth(stem, key, &why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->spp, 8);
  EXPECT_EQ(back->batches, 1);
  EXPECT_EQ(back->code, "code-1");
  EXPECT_EQ(back->about_value("scene"), "a box");
  EXPECT_EQ(back->about_value("nothing"), "");
  EXPECT_EQ(back->mean.pixels, t.mean.pixels);
  EXPECT_EQ(back->standard_error.pixels, t.standard_error.pixels);
  EXPECT_TRUE(gi::load_truth(stem, {"abc", "any", 6, 4})) << "a reader that takes any code";
}

TEST(Truth, EveryDamageIsRefusedInOneLine) {
  const fs::path stem = scratch("damaged");
  const gi::Truth good = small_truth();
  gi::save_truth(good, stem);
  const std::string pfm = gi_test::file_text(stem.string() + ".pfm"), se = gi_test::file_text(stem.string() + "_stderr.pfm");
  const std::string text = gi_test::file_text(stem.string() + ".txt");
  // A picture written as a lesson would write it, its checksum left as it was.
  const auto picture = [](gi::Image image, float value, bool all) {
    for (gi::Pixel& p : image.pixels) {
      p = gi::Pixel(value);
      if (!all) break;
    }
    const fs::path file = scratch("picture.pfm");
    gi::write_pfm(image, file);
    return gi_test::file_text(file);
  };
  const struct {
    const char* what;
    std::string txt, mean, stderr_;
    const char* reason;
  } cases[] = {
      {"the standard-error picture copied over the mean", text, se, se, ".pfm fails its checksum"},
      {"one pixel 1e30", text, picture(good.mean, 1e30f, false), se, ".pfm fails its checksum"},
      {"every pixel 1e-3", text, picture(good.mean, 1e-3f, true), se, ".pfm fails its checksum"},
      {"a truncated picture", text, pfm.substr(0, pfm.size() / 2), se, "is missing or not 6x4"},
      {"a flipped byte in the error picture", text, pfm, se.substr(0, 40) + char(se[40] ^ 1) + se.substr(41),
       "_stderr.pfm fails its checksum"},
      {"a flipped byte in the text", text.substr(0, 60) + char(text[60] ^ 1) + text.substr(61), pfm, se,
       "its text fails its checksum"},
      {"a truncated text", text.substr(0, text.size() / 2), pfm, se, "no checksum of its text"},
      {"the text of the old format", "scene x\nfingerprint abc\nwidth 6\n", pfm, se, "no checksum of its text"},
      {"a text a hostile hand made huge", text + "# " + std::string(1 << 17, 'x') + '\n', pfm, se, "too large"},
      {"no text", "", pfm, se, "no such file"},
  };
  for (const auto& c : cases) {
    fs::remove(stem.string() + ".txt");
    if (!c.txt.empty()) overwrite(stem.string() + ".txt", c.txt);
    overwrite(stem.string() + ".pfm", c.mean);
    overwrite(stem.string() + "_stderr.pfm", c.stderr_);
    std::string why;
    EXPECT_FALSE(gi::load_truth(stem, key, &why)) << c.what;
    EXPECT_NE(why.find(c.reason), std::string::npos) << c.what << ": " << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << c.what << ": one line";
  }
}

TEST(Truth, ATruthOfAnotherSceneSizeOrCodeIsRefused) {
  const fs::path stem = scratch("foreign");
  gi::save_truth(small_truth(), stem);
  std::string why;
  EXPECT_FALSE(gi::load_truth(stem, {"other", "code-1", 6, 4}, &why));
  EXPECT_NE(why.find("another scene or other settings"), std::string::npos) << why;
  EXPECT_FALSE(gi::load_truth(stem, {"abc", "code-1", 12, 8}, &why));
  EXPECT_NE(why.find("it is 6x4, not 12x8"), std::string::npos) << why;
  EXPECT_FALSE(gi::load_truth(stem, {"abc", "code-2", 6, 4}, &why));
  EXPECT_NE(why.find("other library code"), std::string::npos) << why;
}

TEST(Truth, ForgedButImplausiblePicturesAreRefused) {
  // Written whole with their checksums, as a careless tool would: what they say is
  // still checked. A NaN, a negative radiance, and a mean no brighter than its error bar
  // anywhere (the error picture saved as the mean).
  const fs::path stem = scratch("forged");
  std::string why;
  for (const float bad : {std::nanf(""), -1.0f}) {
    gi::Truth t = small_truth();
    t.mean.at(1, 0) = gi::Pixel(bad);
    gi::save_truth(t, stem);
    EXPECT_FALSE(gi::load_truth(stem, key, &why)) << bad;
    EXPECT_NE(why.find("negative or not a number"), std::string::npos) << why;
  }
  gi::Truth t = small_truth();
  t.mean = t.standard_error;
  gi::save_truth(t, stem);
  EXPECT_FALSE(gi::load_truth(stem, key, &why));
  EXPECT_NE(why.find("no smaller than its mean anywhere"), std::string::npos) << why;
  // One sample per pixel leaves the error unmeasured (0): a truth all the same.
  gi::Truth one = small_truth();
  one.standard_error = gi::Image(6, 4);
  one.spp = 1;
  gi::save_truth(one, stem);
  EXPECT_TRUE(gi::load_truth(stem, key, &why)) << why;
}

TEST(Truth, BatchesPoolLikeOneSetOfSamples) {
  // {1, 3} and {5, 7, 9} pooled are {1, 3, 5, 7, 9}: mean 5, s^2 = 10, se^2 = 10 / 5.
  const gi::Truth pooled = gi::combine(one_pixel({1, 3}), one_pixel({5, 7, 9}));
  EXPECT_EQ(pooled.spp, 5);
  EXPECT_EQ(pooled.batches, 2);
  EXPECT_NEAR(pooled.mean.pixels[0].x, 5.0, 1e-6);
  EXPECT_NEAR(pooled.standard_error.pixels[0].x, std::sqrt(2.0), 1e-6);
  gi::Truth other = one_pixel({1, 2});
  other.fingerprint = "g";
  EXPECT_THROW(gi::combine(one_pixel({1, 3}), other), std::invalid_argument);
}

TEST(Truth, RelativeErrorsAndDownsampling) {
  gi::Image reference(4, 2, gi::Pixel(2.0f)), test(4, 2, gi::Pixel(2.0f));
  test.at(0, 0) = gi::Pixel(3.0f);  // +50% in one pixel of eight
  EXPECT_NEAR(gi::relative_rms_error(test, reference), std::sqrt(0.25 / 8), 1e-7);
  EXPECT_NEAR(gi::relative_rms_error(test, reference, 2), std::sqrt(0.125 * 0.125 / 2), 1e-7);
  EXPECT_THROW(gi::relative_rms_error(test, reference, 3), std::invalid_argument);
  gi::Truth r;
  r.mean = reference;
  r.mean.at(1, 1) = gi::Pixel(6.0f);
  r.standard_error = gi::Image(4, 2, gi::Pixel(0.2f));
  EXPECT_NEAR(gi::relative_standard_error(r.standard_error, r.mean), std::sqrt((7 * 0.01 + 0.2 * 0.2 / 36) / 8), 1e-6);
  const gi::Truth half = gi::downsample(r, 2);
  ASSERT_EQ(half.mean.width, 2);
  EXPECT_NEAR(half.mean.at(0, 0).x, (2 + 2 + 2 + 6) / 4.0, 1e-6);
  EXPECT_NEAR(half.standard_error.at(0, 0).x, std::sqrt(4 * 0.04) / 4, 1e-6) << "independent errors: sqrt(sum) / 4";
}

TEST(Truth, AScoreIsTheErrorAndBothNoises) {
  // The film's own noise is its standard errors over the mask's blocks: scored against
  // itself, a film's error is 0 and its own noise equals the truth's.
  gi::Truth truth = small_truth();
  truth.mask = gi::interior_blocks(std::vector<int>(24, 0), 6, 4, 2);
  ASSERT_EQ(truth.mask.count(), 0) << "every block touches the picture's border";
  truth.mask = {2, 3, 2, {1, 1, 1, 1, 1, 1}};
  const gi::Score s = gi::score(noisy_film(), truth);
  EXPECT_EQ(s.error.relative_rms, 0.0);
  EXPECT_DOUBLE_EQ(s.own_noise.relative_rms, s.truth_noise.relative_rms);
  EXPECT_GT(s.truth_noise.relative_rms, 0.0);
  const gi::Score other = gi::score(gi::film_mean(noisy_film(2)), truth);
  EXPECT_GT(other.error.relative_rms, 0.0);
  EXPECT_EQ(other.own_noise.relative_rms, 0.0) << "a picture without a film has no error bar of its own";
}

TEST(CachedTruth, RendersOnceReadsBackAndRendersAgainWhatItRefuses) {
  const fs::path stem = scratch("cache");
  for (const fs::path& f : gi::truth_files(stem)) fs::remove(f);
  int renders = 0;
  const auto render = [&](const std::string&) { return ++renders, noisy_film(); };
  const gi::CachedTruth first = gi::cached_truth(stem, key, 1, render);
  EXPECT_FALSE(first.from_cache);
  EXPECT_EQ(first.reason, "none kept");
  const gi::CachedTruth second = gi::cached_truth(stem, key, 1, render);
  EXPECT_TRUE(second.from_cache) << second.reason;
  EXPECT_EQ(renders, 1);
  EXPECT_EQ(second.truth.mean.pixels, first.truth.mean.pixels);
  // Other code: rendered again into the same files, and good again afterwards.
  const gi::CachedTruth other = gi::cached_truth(stem, {"abc", "code-2", 6, 4}, 1, render);
  EXPECT_FALSE(other.from_cache);
  EXPECT_NE(other.reason.find("other library code"), std::string::npos) << other.reason;
  EXPECT_TRUE(gi::cached_truth(stem, {"abc", "code-2", 6, 4}, 1, render).from_cache);
  // A truncated picture: rendered again, whole.
  const std::string pfm = gi_test::file_text(stem.string() + ".pfm");
  fs::resize_file(stem.string() + ".pfm", pfm.size() / 2);
  const gi::CachedTruth again = gi::cached_truth(stem, {"abc", "code-2", 6, 4}, 1, render);
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(gi_test::file_text(stem.string() + ".pfm"), pfm);
  EXPECT_EQ(renders, 3);
}
