#pragma once
// PCG32 (M. E. O'Neill, "PCG: a family of simple fast space-efficient statistically
// good algorithms for random number generation", 2014): 64-bit state, 32-bit output,
// a stream per odd increment. Written out here rather than taken from <random>, whose
// distributions differ between standard libraries: the same seed gives the same
// image on every compiler.
#include <cstdint>

namespace gi {

class Rng {
 public:
  // `stream` selects an independent sequence: the render loop uses the pixel index,
  // so each pixel's numbers do not depend on which thread renders it.
  explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0xda3e39cb94b95bdbULL) {
    state_ = 0;
    inc_ = (stream << 1u) | 1u;
    next_u32();
    state_ += seed;
    next_u32();
  }

  std::uint32_t next_u32() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() {
    const std::uint64_t a = next_u32() >> 5;  // 27 bits
    const std::uint64_t b = next_u32() >> 6;  // 26 bits
    return static_cast<double>((a << 26) | b) * 0x1.0p-53;
  }

  // Uniform integer in [0, n) without modulo bias (rejection of the short tail).
  std::uint32_t below(std::uint32_t n) {
    const std::uint32_t threshold = (0u - n) % n;
    for (;;) {
      const std::uint32_t r = next_u32();
      if (r >= threshold) return r % n;
    }
  }

 private:
  std::uint64_t state_;
  std::uint64_t inc_;
};

}  // namespace gi
