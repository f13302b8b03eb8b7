#include "gi/core/samplers/sample_stream.hpp"

#include <stdexcept>

#include "gi/core/rng.hpp"
#include "gi/core/samplers/owen_scramble.hpp"
#include "gi/core/samplers/seeds.hpp"
#include "gi/core/samplers/sobol.hpp"

namespace gi {

namespace {

double fraction(std::uint32_t digits) { return digits * 0x1p-32; }  // exact, and below 1

// Sobol's point for one pixel and dimension: the three scrambles' seeds come from the
// dimension's seed. First the sample's index is shuffled by an Owen scramble of its own
// digits (highest first): that maps each block of 2^m indices onto a block of 2^m, so
// the first 2^m samples are still a (0,m,2)-net, but which net points they are, and in
// which order, belongs to this pixel and dimension alone -- without it every dimension
// would walk the sequence in step, and a path's decisions would move together. Then each
// coordinate is Owen-scrambled with a seed of its own, by owen_scramble itself, the
// lecture's scramble digit by digit (exercise 14.7): a picture made with Sobol' numbers
// shows the scramble its reader wrote. The index shuffle only has to decorrelate the
// dimensions, and takes the hashed scramble, five multiplications.
struct SobolSeeds {
  std::uint32_t shuffle, x, y;
};
SobolSeeds sobol_seeds(std::uint64_t dimension_seed) {
  const std::uint64_t more = mix64(dimension_seed);
  return {low_bits(dimension_seed), high_bits(dimension_seed), low_bits(more)};
}

}  // namespace

const char* sequence_name(SamplerKind kind) {
  switch (kind) {
    case SamplerKind::Independent: return "independent";
    case SamplerKind::Stratified: return "stratified";
    case SamplerKind::Sobol: return "Sobol'";
  }
  return "?";
}

std::vector<std::string> sequence_option_names() { return {"independent", "stratified", "sobol"}; }

SamplerKind sequence_from_name(const std::string& name) {
  const std::vector<std::string> names = sequence_option_names();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (name == names[k]) return static_cast<SamplerKind>(k);
  throw std::invalid_argument("unknown number sequence '" + name + "' (independent, stratified, sobol)");
}

SampleSequence make_sample_sequence(SamplerKind kind, std::uint64_t seed, std::uint32_t samples_per_pixel) {
  if (samples_per_pixel == 0) throw std::invalid_argument("sampler: samples per pixel must be at least 1, got 0");
  return {kind, seed, samples_per_pixel, strata_grid(samples_per_pixel)};
}

SampleStream::SampleStream(const SampleSequence& sequence, std::uint64_t pixel, std::uint32_t sample_index)
    : kind_(sequence.kind),
      samples_per_pixel_(sequence.samples_per_pixel),
      strata_(sequence.strata),
      pixel_(pixel),
      index_(sample_index),
      pixel_seed_(child_seed(sequence.seed, pixel)) {
  switch (kind_) {
    case SamplerKind::Independent: sample_seed_ = child_seed(pixel_seed_, index_); break;
    case SamplerKind::Stratified: sample_seed_ = child_seed(pixel_seed_, index_ / samples_per_pixel_); break;
    case SamplerKind::Sobol: sample_seed_ = 0; break;  // one scramble for all the pixel's samples
  }
}

double SampleStream::get_1d(std::uint32_t dimension) const {
  switch (kind_) {
    case SamplerKind::Independent: {
      Rng rng(child_seed(sample_seed_, dimension), pixel_);
      return rng.uniform();
    }
    case SamplerKind::Stratified: {
      const std::uint32_t n = samples_per_pixel_, j = index_ % n;
      const std::uint64_t dimension_seed = child_seed(sample_seed_, dimension);
      const std::uint32_t stratum = permutation_element(j, n, dimension_seed);
      return jittered_1d(stratum, n, low_bits(child_seed(mix64(dimension_seed), j)));
    }
    case SamplerKind::Sobol: {
      const SobolSeeds s = sobol_seeds(child_seed(pixel_seed_, dimension));
      const std::uint32_t i = owen_scramble_hashed(index_, s.shuffle);
      return fraction(owen_scramble(sobol(i, 0), s.x));
    }
  }
  return 0;
}

vec2 SampleStream::get_2d(std::uint32_t dimension) const {
  switch (kind_) {
    case SamplerKind::Independent: {
      Rng rng(child_seed(sample_seed_, dimension), pixel_);
      const double x = rng.uniform();
      return {x, rng.uniform()};
    }
    case SamplerKind::Stratified: {
      const std::uint32_t j = index_ % samples_per_pixel_;
      const std::uint64_t dimension_seed = child_seed(sample_seed_, dimension);
      const std::uint32_t stratum = permutation_element(j, samples_per_pixel_, dimension_seed);
      const std::uint64_t jitter = child_seed(mix64(dimension_seed), j);
      return jittered_2d(stratum, strata_, low_bits(jitter), high_bits(jitter));
    }
    case SamplerKind::Sobol: {
      const SobolSeeds s = sobol_seeds(child_seed(pixel_seed_, dimension));
      const std::uint32_t i = owen_scramble_hashed(index_, s.shuffle);
      return {fraction(owen_scramble(sobol(i, 0), s.x)), fraction(owen_scramble(sobol(i, 1), s.y))};
    }
  }
  return {0, 0};
}

}  // namespace gi
