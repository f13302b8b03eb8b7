#pragma once
// Owen's scramble (A. B. Owen, "Randomly permuted (t,m,s)-nets and (t,s)-sequences",
// 1995): randomise a net without breaking it. Write a coordinate in base 2,
// x = 0.d_1 d_2 d_3 ..., and flip each digit d_k or not by a random bit drawn afresh
// for every value of the digits above it:
//   d'_k = d_k xor r(d_1 ... d_(k-1))
// Flipping d_1 swaps the halves [0, 1/2) and [1/2, 1); flipping d_2 swaps the two
// quarters of the left half (when d_1 = 0) or of the right half (d_1 = 1), each by a
// bit of its own; and so on down. The random bits sit at the nodes of the binary tree
// of halvings: the interval of depth k - 1 with digits d_1 ... d_(k-1) is node
//   2^(k-1) + (d_1 ... d_(k-1) read as a binary number)
// (node 1 is [0, 1), its halves are nodes 2 and 3, theirs 4 ... 7).
//
// What it keeps: each dyadic interval [a 2^-p, (a + 1) 2^-p) is mapped onto one of the
// same length, so a net stays a net (Sobol's first 2^m points stay one point in every
// elementary interval). What it gives: each point alone is uniform in [0, 1), so the
// estimate is unbiased; and for a smooth integrand its variance falls as
// O(N^-3 (log N)^(s-1)) in s dimensions (Owen, "Scrambled net variance for integrals of
// smooth functions", 1997): an RMS error near N^-3/2 in two, where jittered sampling
// reaches N^-1. Flipping each digit by one bit for all intervals alike (a "random
// digital shift", r without its argument) keeps the net and is unbiased too, but is
// a far smaller randomisation: for a smooth integrand the error falls only as N^-1.
#include <cstdint>

namespace gi {

// The random bit of a node of the binary tree of intervals, for one scramble (seed).
int scramble_bit(std::uint32_t seed, std::uint64_t node);

// Owen's scramble of the 32 digits of v (the fraction v 2^-32, d_1 in the highest bit),
// as defined above: one random bit per digit, each from scramble_bit at its node.
std::uint32_t owen_scramble(std::uint32_t v, std::uint32_t seed);

// The bits of v in the opposite order: bit 0 to bit 31, bit 1 to bit 30, ...
constexpr std::uint32_t reverse_bits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);  // swap neighbours
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);  // pairs
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);  // nibbles
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);  // bytes
  return (v >> 16) | (v << 16);
}

// A scramble of the same kind from a hash of the whole word, at five multiplications
// instead of 32 hashes (Laine and Karras, "Stratified sampling for stochastic
// transparency", 2011; for Sobol' points, Burley, "Practical hash-based Owen
// scrambling", 2020; these constants from Vegdahl, "Building a better LK hash", 2021).
// With the digits reversed, d_1 in bit 0, every step changes bit k by an amount that
// depends only on the bits below it, the digits above d_k:
//   x ^= x * c   (c even: bit k of x c comes from bits 0 ... k-1 of x)
//   x += seed,  x *= odd   (carries run only upwards)
// so each step is a nested permutation of the digits, and so is their composition. It
// reaches only some of Owen's scrambles (2^32 seeds against 2^(2^32 - 1) trees of
// bits), but those it reaches pass the same tests (tests/core/owen_scramble_test.cpp).
constexpr std::uint32_t owen_scramble_hashed(std::uint32_t v, std::uint32_t seed) {
  std::uint32_t x = reverse_bits(v);
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return reverse_bits(x);
}

}  // namespace gi
