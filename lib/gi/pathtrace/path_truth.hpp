#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "gi/image/image.hpp"
#include "gi/pathtrace/path_trace.hpp"

namespace gi {

// A converged path-traced picture, the truth other methods are scored against, kept on
// disk with its own error bar as three files beside each other:
//   STEM.pfm         the mean radiance of each pixel, linear floats
//   STEM_stderr.pfm  the standard error of each pixel's mean, per channel: sqrt(s^2 / n)
//   STEM.txt         what it is: the scene's fingerprint, size, samples per pixel, seed,
//                    strategy, depth limits, time, and the relative standard errors
// The text file is written last and removed first, so a set cut short by a crash or a
// full disk is never trusted. The fingerprint covers everything that changes the
// expected picture (geometry, materials, camera, size, depth limit), so a reference
// of a scene that has since changed (e.g. new reflectances) is refused, not used.
struct PathReference {
  std::string scene;
  std::string fingerprint;
  Image mean;
  Image standard_error;
  long long spp = 0;
  std::uint64_t seed = 0;  // batch b (0, 1, ...) drew from seed + b
  int batches = 1;
  PathSettings settings;
  double seconds = 0;
};

// A hash (FNV-1a, 64 bits, as 16 hex digits) of the scene as the path tracer sees it
// and of what else fixes the converged picture.
std::string reference_fingerprint(const PathScene& scene, const PathSettings& settings, int width, int height);

// SHA-256 of the sources of the path tracer and every topic it uses, computed when the
// library is built (cmake/CodeFingerprint.cmake). A reference a lesson renders and keeps
// adds it to its fingerprint, so that changed code -- a student's lab 14 -- renders it
// again. The stored Cornell box reference leaves it out: it is the truth a student's
// code is measured against, whatever that code is.
const char* path_code_fingerprint();

// The reference from a film: its mean and the standard error of the mean.
PathReference reference_from_film(const Film& film, const std::string& scene, const std::string& fingerprint,
                                  std::uint64_t seed, const PathSettings& settings, double seconds);

// Two references of the same picture drawn with different seeds, as one: the pooled
// mean and spread of all their samples (Chan et al.'s update of Welford's sums):
//   n = n_a + n_b,  mean = (n_a m_a + n_b m_b) / n,
//   M2 = M2_a + M2_b + (m_b - m_a)^2 n_a n_b / n,  with M2 = se^2 n (n - 1).
// So a long reference can be rendered batch by batch, and made longer later.
PathReference combine(const PathReference& a, const PathReference& b);

// Writes the three files (creating the folder). Throws std::runtime_error on failure.
void save_reference(const PathReference& reference, const std::filesystem::path& stem);

// The reference at `stem` if all three files are there, well formed and made for
// `fingerprint`; otherwise nothing, with the reason in *why (when given).
std::optional<PathReference> load_reference(const std::filesystem::path& stem, const std::string& fingerprint,
                                            std::string* why = nullptr);

// Relative RMS difference sqrt(mean((t - r)^2 / r^2)) over pixels and channels, after
// averaging both pictures over blocks of block x block pixels (block 1: per pixel).
// Values whose reference is below 1e-3 of the reference's mean are left out (black
// corners would divide by zero). Throws std::invalid_argument for different sizes.
double relative_rms_error(const Image& test, const Image& reference, int block = 1);

// The same measure of the reference's own noise: sqrt(mean(se^2 / r^2)), with a block's
// standard error sqrt(sum se^2) / block^2 (its pixels' errors are independent).
double relative_standard_error(const PathReference& reference, int block = 1);

// The reference at a lower resolution: each factor x factor block of pixels averaged
// (exactly what a box-filtered picture of the lower resolution converges to), its
// standard error combined as for a block. Throws unless factor divides both sizes.
PathReference downsample(const PathReference& reference, int factor);

}  // namespace gi
