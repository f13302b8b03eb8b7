#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/render/film.hpp"
#include "gi/render/picture_error.hpp"

namespace gi {

// The truth a method is scored against: a converged picture with its own error bar,
// made by other means than the method it scores (a path tracer's many samples, a
// many-ray render), kept on disk as three files beside each other:
//   STEM.pfm         the mean radiance of each pixel, linear floats
//   STEM_stderr.pfm  the standard error of each pixel's mean, per channel (0 where one
//                    sample per pixel left it unmeasured)
//   STEM.txt         what it is, a line "name value" each: the fingerprint of what fixes
//                    the expected picture, the code that made it ("any" for a truth kept
//                    whatever the code), size, samples, seed, time, the method's own
//                    settings; then the checksums of both pictures and of the lines above.
// Written pictures first, the text last (and removed first), each file whole or not at
// all: a set cut short is never trusted. Read back only when every check passes.
struct Truth {
  std::string fingerprint;  // what must match for it to be used: scene, size, what changes the expectation
  std::string code = "any";  // the fingerprint of the code that made it, or "any"
  Image mean;
  Image standard_error;
  long long spp = 0;
  std::uint64_t seed = 0;  // batch b (0, 1, ...) drew from seed + b
  int batches = 1;
  double seconds = 0;
  // Settings a reader wants to see ("scene cornell", "strategy mis"): stored, not checked.
  std::vector<std::pair<std::string, std::string>> about;
  // Where pictures are scored against it (interior_blocks): set by whoever knows the
  // scene; not stored.
  BlockMask mask;

  std::string about_value(const std::string& name) const;  // "" when it says nothing of it
};

// A picture against the truth, over the truth's mask (picture_error.hpp): its error,
// the truth's own noise (what a picture equal to the truth would still score) and the
// picture's own noise, from its film's standard errors (0 for a picture without a film:
// a deterministic method's, or one whose spread was not kept). Throws
// std::invalid_argument as picture_error does (a mask of no block, another size).
struct Score {
  PictureError error;
  PictureError truth_noise;
  PictureError own_noise;
};
Score score(const Image& picture, const Truth& truth);
Score score(const Film& film, const Truth& truth);

// What a reader expects of a truth; code "any" accepts a truth made by any code.
struct TruthKey {
  std::string fingerprint;
  std::string code = "any";
  int width = 0, height = 0;
};

// A film's truth: its mean and the standard error of each pixel's mean.
Truth truth_from_film(const Film& film, const TruthKey& key, std::uint64_t seed, double seconds,
                      std::vector<std::pair<std::string, std::string>> about = {});

// Writes the three files (creating the folder). Throws std::runtime_error on failure.
void save_truth(const Truth& truth, const std::filesystem::path& stem);

// The truth at `stem` if all three files are there and pass every check: the text well
// formed and its checksum right, made for `key` (fingerprint, code, size), both pictures
// of the size announced with the checksums announced, every value finite and not
// negative, and a standard error below its mean somewhere (a picture as uncertain as it
// is bright everywhere is noise, or the error picture written over the mean). Otherwise
// nothing, with the reason, one line naming the file, in *why (when given).
std::optional<Truth> load_truth(const std::filesystem::path& stem, const TruthKey& key, std::string* why = nullptr);

// The three files of a truth at `stem`: STEM.txt, STEM.pfm, STEM_stderr.pfm.
std::vector<std::filesystem::path> truth_files(const std::filesystem::path& stem);
// Is any of them there?
bool truth_files_exist(const std::filesystem::path& stem);

// Two truths of the same picture drawn with different seeds, as one: the pooled mean and
// spread of all their samples (Chan et al.'s update of Welford's sums):
//   n = n_a + n_b,  mean = (n_a m_a + n_b m_b) / n,
//   M2 = M2_a + M2_b + (m_b - m_a)^2 n_a n_b / n,  with M2 = se^2 n (n - 1).
// So a long truth can be rendered batch by batch, and made longer later.
Truth combine(const Truth& a, const Truth& b);

// The truth at a lower resolution: each factor x factor block of pixels averaged
// (exactly what a box-filtered picture of the lower resolution converges to), its
// standard error sqrt(sum se^2) / factor^2 (the pixels' errors are independent).
// Throws std::invalid_argument unless factor divides both sizes.
Truth downsample(const Truth& truth, int factor);

// A truth kept in a lesson's output folder: read back when one made for `key` is there,
// else made by `render` (a film of at least one sample per pixel; it is told why) and saved.
struct CachedTruth {
  Truth truth;
  std::filesystem::path stem;
  bool from_cache = false;  // read back, rather than rendered now
  std::string reason;       // why it was rendered: "none kept", "... made by other library code" ...
};
CachedTruth cached_truth(const std::filesystem::path& stem, const TruthKey& key, std::uint64_t seed,
                         const std::function<Film(const std::string& reason)>& render,
                         const std::vector<std::pair<std::string, std::string>>& about = {});

}  // namespace gi
