#pragma once
// The one place that knows the processor: lanes of four numbers, the mask of a lane
// comparison, and which functions are compiled twice for AVX2. Everything else in the
// library is the same source on every machine.
//
// Lanes are GCC's and Clang's vector extension: + - * < ?: on two of them work lane by
// lane, as four scalar operations would (IEEE arithmetic rounds each lane as it rounds a
// scalar), and the compiler emits SSE on x86-64, NEON on ARM64, or scalar code on a
// processor with neither. Only reading the lanes' verdicts into an int needs an
// instruction of its own: SSE's movmskps and movmskpd, on NEON an AND with 1, 2, 4, 8
// and a sum across the lanes; elsewhere (or built with GI_PORTABLE_SIMD) a loop over
// the lanes, which gives the same bits. A test holds each to the loop.
#include <bit>
#include <cstdint>
#include <cstring>

#if !defined(GI_PORTABLE_SIMD) && defined(__SSE2__)
#define GI_SIMD_SSE2 1
#include <emmintrin.h>
#elif !defined(GI_PORTABLE_SIMD) && defined(__aarch64__) && defined(__ARM_NEON)
#define GI_SIMD_NEON 1
#include <arm_neon.h>
#endif

// GI_FOUR_DOUBLES_KERNEL marks a function whose lanes are four doubles: with GCC on
// x86-64 Linux it is compiled twice, for AVX2 (the four in one instruction) and for
// the baseline (in two), and the program picks one as it starts (an ifunc, which
// Windows and macOS do not have, and which Clang will not combine with flatten);
// everywhere it is flattened (every call in it built into it).
#if !defined(GI_PORTABLE_SIMD) && defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && !defined(__clang__)
#define GI_FOUR_DOUBLES_KERNEL [[gnu::target_clones("avx2", "default"), gnu::flatten]]
#else
#define GI_FOUR_DOUBLES_KERNEL [[gnu::flatten]]
#endif

namespace gi::simd {

using float4 = float __attribute__((vector_size(16)));
using double4 = double __attribute__((vector_size(32)));
// (No function here takes or returns a double4 by value: without AVX that would be
// a call convention of GCC's own, which it warns about. Spell them out in place.)
inline float4 splat(float x) { return float4{x, x, x, x}; }

// Four values from memory with no alignment asked (memcpy compiles to one load).
inline float4 load(const float* from) {
  float4 v;
  std::memcpy(&v, from, sizeof v);
  return v;
}

// Bit j set where lane j is true, lane by lane: the portable path.
template <class Mask>
unsigned lane_mask_portable(const Mask& lanes) {
  static_assert(sizeof lanes == 16 || sizeof lanes == 32, "four lanes of 32 or 64 bits");
  unsigned mask = 0;
  for (int j = 0; j < 4; ++j) mask |= lanes[j] != 0 ? 1u << j : 0u;
  return mask;
}

// Bit j set where lane j is true, in one or two instructions where the processor has
// them. `lanes` is the result of comparing two float4 (or two double4).
template <class Mask>
unsigned lane_mask(const Mask& lanes) {
  static_assert(sizeof lanes == 16 || sizeof lanes == 32, "four lanes of 32 or 64 bits");
#if defined(GI_SIMD_SSE2)
  if constexpr (sizeof lanes == 16) {
    return static_cast<unsigned>(_mm_movemask_ps(std::bit_cast<__m128>(lanes)));  // the four sign bits
  } else {  // two at a time: SSE holds two doubles
    struct Halves { __m128d low, high; };
    const auto h = std::bit_cast<Halves>(lanes);
    return static_cast<unsigned>(_mm_movemask_pd(h.low) | _mm_movemask_pd(h.high) << 2);
  }
#elif defined(GI_SIMD_NEON)
  const uint32x4_t weights = {1, 2, 4, 8};
  if constexpr (sizeof lanes == 16) {
    return vaddvq_u32(vandq_u32(std::bit_cast<uint32x4_t>(lanes), weights));
  } else {  // each 64-bit lane narrowed to 32 bits (all ones stay all ones), then as above
    struct Halves { uint64x2_t low, high; };
    const auto h = std::bit_cast<Halves>(lanes);
    return vaddvq_u32(vandq_u32(vcombine_u32(vmovn_u64(h.low), vmovn_u64(h.high)), weights));
  }
#else
  return lane_mask_portable(lanes);
#endif
}

}  // namespace gi::simd
