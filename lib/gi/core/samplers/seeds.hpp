#pragma once
// Seeds for the parts of a render: one for each pixel of a seed, one for each sample
// of a pixel, one for each decision of a sample. A sampler that hashes its way down
// this tree gives every (pixel, sample, decision) its own random numbers without
// storing any, and in any order: the same numbers whichever thread asks, and when.
#include <cstdint>

namespace gi {

// SplitMix64's output function (Steele, Lea and Flood, "Fast splittable pseudorandom
// number generators", 2014): two multiply-xorshift rounds, a bijection of 64-bit
// words in which every input bit changes about half the output bits.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// The seed of part `child` of whatever `parent` seeds. The golden-ratio constant keeps
// child 0 from mixing to 0 (mix64(0) = 0).
constexpr std::uint64_t child_seed(std::uint64_t parent, std::uint64_t child) {
  return mix64(parent ^ mix64(child + 0x9e3779b97f4a7c15ull));
}

// 32 random bits from a seed, as the samplers' scrambles and jitters take them.
constexpr std::uint32_t low_bits(std::uint64_t seed) { return static_cast<std::uint32_t>(seed); }
constexpr std::uint32_t high_bits(std::uint64_t seed) { return static_cast<std::uint32_t>(seed >> 32); }

}  // namespace gi
