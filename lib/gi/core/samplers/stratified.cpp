#include "gi/core/samplers/stratified.hpp"

#include <bit>
#include <cmath>
#include <stdexcept>

#include "gi/core/samplers/seeds.hpp"

namespace gi {

namespace {

// The largest double below 1: a quotient that rounds up to 1 is put back inside [0, 1).
constexpr double below_one = 0x1.fffffffffffffp-1;

// A random bijection of [0, 4^h) (h bits a half), by a Feistel network: split x into a
// left and a right half and, round after round, replace (left, right) by
//   (right, left xor F(right))
// with F a hash of the round's key and the right half. Each round is undone by the
// same step backwards, whatever F is (Luby and Rackoff, 1988). Small domains need many
// rounds: on 16 elements, with F truly random, the chance of each ordered pair of
// elements is off from 1/240 by 1% in total after 6 rounds and by 0.07% after 10
// (computed exactly; tests/core/stratified_test.cpp measures it for this F).
std::uint32_t feistel(std::uint32_t x, int h, std::uint64_t seed) {
  const std::uint32_t half = (1u << h) - 1;
  std::uint32_t left = x >> h, right = x & half;
  for (std::uint64_t round = 0; round < 10; ++round) {
    const std::uint32_t f = low_bits(mix64((seed + round * 0x9e3779b97f4a7c15ull) ^ right)) & half;
    const std::uint32_t next = left ^ f;
    left = right;
    right = next;
  }
  return (left << h) | right;
}

}  // namespace

StrataGrid strata_grid(std::uint32_t n) {
  if (n == 0) throw std::invalid_argument("stratified sampling: the number of strata must be at least 1, got 0");
  auto root = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
  while (root * root > n) --root;  // floor(sqrt(n)), exactly, whatever the rounding
  while ((root + 1) * (root + 1) <= n) ++root;
  for (std::uint64_t nx = root;; --nx)
    if (n % nx == 0) return {static_cast<std::uint32_t>(nx), static_cast<std::uint32_t>(n / nx)};
}

// "Cycle walking": permute within the smallest 4^h >= n, and step again while the value
// lies at or beyond n. The walk ends, at the latest back at i itself on the
// permutation's cycle through i, and takes fewer than four steps on average (4^h < 4n);
// the values below n that it stops at form a permutation of [0, n).
std::uint32_t permutation_element(std::uint32_t i, std::uint32_t n, std::uint64_t seed) {
  const int bits = static_cast<int>(std::bit_width(n - 1));  // 2^bits >= n
  const int h = (bits + 1) / 2;
  std::uint32_t x = i;
  do x = feistel(x, h, seed);
  while (x >= n);
  return x;
}

double jittered_1d(std::uint32_t stratum, std::uint32_t n, std::uint32_t jitter) {
  return std::min((stratum + jitter * 0x1p-32) / n, below_one);
}

vec2 jittered_2d(std::uint32_t stratum, StrataGrid grid, std::uint32_t jitter_x, std::uint32_t jitter_y) {
  return {jittered_1d(stratum % grid.nx, grid.nx, jitter_x), jittered_1d(stratum / grid.nx, grid.ny, jitter_y)};
}

}  // namespace gi
