#pragma once
// The random numbers of one sample of one pixel, decision by decision. A Monte Carlo
// estimator of a pixel averages N samples; each sample makes a fixed list of decisions
// (where in the pixel, where on the lens, then at each bounce which light, where on it,
// which direction, ...), and each decision reads the numbers of its own dimension:
//   stream.get_2d(d)   the point in [0, 1)^2 of dimension d, for this pixel and sample
//   stream.get_1d(d)   the number in [0, 1) of dimension d
// Across the N samples of a pixel, each dimension alone is spread as well as the kind of
// sampler can spread it:
//   Independent  every number uniform and independent (PCG32, gi::Rng): error ~ N^-1/2
//   Stratified   sample i of N in stratum pi_d(i) of N, a random permutation pi_d per
//                dimension (stratified.hpp); 2D strata an nx x ny grid. Samples N b to
//                N b + N - 1 are stratified set b (a renderer may go on past N)
//   Sobol        the (0,2)-sequence of Sobol' (sobol.hpp), each coordinate Owen-scrambled
//                per pixel and dimension by owen_scramble (exercise 14.7): the first 2^m
//                samples, and every later block of 2^m, are a (0,m,2)-net; no N needs
//                to be known
// and different dimensions, and different pixels, are independent of each other. Only
// within a dimension are the samples spread: a path's 2D decisions are not spread
// jointly in 4D or more ("padding" 2D points, as pbrt-v4's PaddedSobolSampler and
// Cycles' PMJ sampler do), which keeps deep bounces as well spread as the first.
//
// Everything is a function of (sampler, pixel, sample index, dimension): no state, no
// order of calls, no thread in it, and integer arithmetic to the last step (numbers are
// integers times 2^-32 or 2^-53), so the same on every compiler and machine.
#include <cstdint>
#include <string>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/core/samplers/stratified.hpp"

namespace gi {

// The number sequence a render's samples read, a choice apart from the pixel pattern
// (render/pixel_samplers.hpp, whose names are sampler_name's): one names where in the
// pixel the eye rays go, the other which numbers every decision of a sample reads.
enum class SamplerKind { Independent, Stratified, Sobol };
const char* sequence_name(SamplerKind kind);  // "independent", "stratified", "Sobol'": as tables print it
// The names an option takes, "independent", "stratified", "sobol", and back;
// sequence_from_name throws std::invalid_argument for any other.
std::vector<std::string> sequence_option_names();
SamplerKind sequence_from_name(const std::string& name);

struct SampleSequence {
  SamplerKind kind = SamplerKind::Independent;
  std::uint64_t seed = 0;
  std::uint32_t samples_per_pixel = 1;  // N: the strata of Stratified; the others do not need it
  StrataGrid strata;                    // Stratified's 2D grid for N (made by make_sample_sequence)
};
// Throws std::invalid_argument for N = 0.
SampleSequence make_sample_sequence(SamplerKind kind, std::uint64_t seed, std::uint32_t samples_per_pixel);

// The dimensions of a path's decisions: each decision always reads the same dimension,
// whether or not the decisions before it were taken (a path that meets a mirror takes no
// light sample there, yet its next bounce reads the same dimensions as every other
// path's next bounce):
//   0 the point in the pixel (2D)      1 the point on the lens (2D)
//   then per bounce b = 0, 1, ...:     2 + 5b  which light (1D)
//     3 + 5b  the point on it (2D)     4 + 5b  the BSDF's direction (2D)
//     5 + 5b  the BSDF's lobe (1D)     6 + 5b  Russian roulette (1D)
enum class Decision { LightChoice, LightPoint, BsdfDirection, BsdfLobe, Roulette };
inline constexpr std::uint32_t pixel_dimension = 0;
inline constexpr std::uint32_t lens_dimension = 1;
inline constexpr std::uint32_t decisions_per_bounce = 5;
constexpr std::uint32_t path_dimension(std::uint32_t bounce, Decision decision) {
  return 2 + decisions_per_bounce * bounce + static_cast<std::uint32_t>(decision);
}

class SampleStream {
 public:
  SampleStream(const SampleSequence& sequence, std::uint64_t pixel, std::uint32_t sample_index);

  double get_1d(std::uint32_t dimension) const;
  vec2 get_2d(std::uint32_t dimension) const;

  // The next dimension, counting from 0, for estimators that take their decisions in
  // a fixed order.
  double next_1d() { return get_1d(next_dimension_++); }
  vec2 next_2d() { return get_2d(next_dimension_++); }

 private:
  SamplerKind kind_;
  std::uint32_t samples_per_pixel_;
  StrataGrid strata_;
  std::uint64_t pixel_;
  std::uint32_t index_;        // of the sample, among the pixel's
  std::uint64_t pixel_seed_;   // the sampler's seed for this pixel
  std::uint64_t sample_seed_;  // Independent: this sample's; Stratified: its stratified set's
  std::uint32_t next_dimension_ = 0;
};

}  // namespace gi
