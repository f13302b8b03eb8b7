#pragma once
// How fast each sampler's error falls as the samples grow, on estimators whose answer
// is known in closed form. For N samples of a pixel, the RMS error of the pixel's mean
// over many pixels (each an independent estimate of the same integral), fitted to
//   RMS error ~ C N^slope
// on a log-log scale. What the theory of each sampler says (stratified.hpp,
// owen_scramble.hpp), for two-dimensional integrands:
//                  independent   stratified   Sobol' (Owen-scrambled)
//   smooth            -1/2          -1           -3/2
//   with a jump       -1/2          -3/4         -3/4
// A jump (an edge, a shadow's border, a light's outline seen by a BSDF ray) caps the
// well-spread samplers at -3/4: the O(sqrt N) strata the edge crosses keep their
// variance. A smooth integrand lets Sobol' pull ahead.
//
// The pixels are a film's, rendered by render_pass with the estimator as the radiance
// function: the one pixel loop of the course, whose numbers (sample_stream.hpp) the
// estimators read as a path tracer's decisions read them.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gi/core/samplers/sample_stream.hpp"
#include "gi/render/render_pass.hpp"

namespace gi {

struct Estimator {
  std::string name;
  double exact = 0;     // the expected value of `sample`, in closed form
  bool smooth = false;  // which row of the table above it belongs to
  std::function<double(PixelSample&)> sample;  // one sample's estimate, from its decisions
};

// The study's four estimators, each a decision of a path at its own dimension:
//   smooth      exp(-(x^2 + y^2)) over the pixel's square, (x, y) where its eye ray
//               crosses it: ((sqrt(pi) / 2) erf(1))^2
//   disk        the indicator of the disk of area 1/2 centred in the pixel
//   light       irradiance at a point from a square light above it, side 1 at height
//               1, radiance 1, by a point drawn uniformly on the light (next-event
//               estimation, the light point's dimension): E = pi L F, F the form factor
//   cosine      the same irradiance by directions drawn with the density cos(theta) / pi
//               (BSDF sampling, the BSDF's dimension): pi L if the ray meets the light,
//               else 0 -- a jump at the light's outline
std::vector<Estimator> study_estimators();

// The irradiance estimators' form factor, from a point to a parallel square of side a
// centred above it at height h: four times Howell's corner factor (A = B = a / 2h),
//   F_corner = 1/(2 pi) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2)) + B / sqrt(1 + B^2) atan(A / sqrt(1 + B^2))]
double form_factor_point_to_centred_square(double a, double h);

// The slope the theory gives (the table above).
double expected_slope(SamplerKind kind, bool smooth);

struct StudySettings {
  std::vector<std::uint32_t> sample_counts{4, 16, 64, 256, 1024, 4096};  // N, squares for the strata
  int pixels = 256;                                                      // independent estimates per N
  std::uint64_t seed = 1;
};

struct StudyRow {
  std::string estimator;
  SamplerKind sampler;
  std::uint32_t samples;       // N
  double rms = 0;              // RMS error of the mean of N samples over the pixels, relative to the exact value
  double rms_standard_error = 0;
};

struct StudySlope {
  std::string estimator;
  SamplerKind sampler;
  double slope = 0, standard_error = 0;  // of the fit (statistical only: the law may bend at small N)
  double expected = 0;
};

struct SamplerStudy {
  std::vector<StudyRow> rows;  // by estimator, then sampler, then N
  std::vector<StudySlope> slopes;
};

// Every pixel's estimate of `estimator`, the mean of its N samples: a film of
// `pixels` x 1 with the sequence `kind` (seed, N), N samples by render_pass's Random
// pattern (its points the sequence's pixel dimension), on `threads` threads (0 = all
// cores; the same numbers for any count). Throws std::invalid_argument for pixels
// outside [1, 16384] or N = 0.
std::vector<double> pixel_estimates(const Estimator& estimator, SamplerKind kind, std::uint64_t seed,
                                    std::uint32_t samples, int pixels, int threads);

// Every estimator with every sampler at every N, over `pixels` pixels (pixel_estimates).
// Each N draws from its own seed, so the points of the fit are independent. Throws
// std::invalid_argument for pixels outside [2, 16384], fewer than 2 sample counts, or a
// count of 0.
SamplerStudy sampler_study(const std::vector<Estimator>& estimators, const std::vector<SamplerKind>& samplers,
                           const StudySettings& settings, int threads);

// The least-squares line through (ln N, ln e), and the standard error of its slope from
// each point's own: with x_k = ln N_k and s_k = se_k / e_k,
//   slope = sum (x_k - mean x)(ln e_k - mean ln e) / S,  se^2 = sum (x_k - mean x)^2 s_k^2 / S^2,
//   S = sum (x_k - mean x)^2.
struct LogLogPoint {
  double samples, error, standard_error;
};
struct Slope {
  double slope = 0, standard_error = 0;
};
Slope fit_log_log_slope(const std::vector<LogLogPoint>& points);

}  // namespace gi
