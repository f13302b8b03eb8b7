#include "gi/core/samplers/owen_scramble.hpp"

#include "gi/core/not_implemented.hpp"
#include "gi/core/samplers/seeds.hpp"

namespace gi {

int scramble_bit(std::uint32_t seed, std::uint64_t node) { return static_cast<int>(child_seed(seed, node) & 1u); }

std::uint32_t owen_scramble(std::uint32_t v, std::uint32_t seed) {
  // BEGIN EXERCISE 14.7 Owen's scramble: the random bit of each digit
  std::uint32_t scrambled = v;
  for (int k = 0; k < 32; ++k) {
    // Digit d_(k+1) is bit 31 - k of v; the k digits above it name its interval's node.
    const std::uint64_t above = std::uint64_t{v} >> (32 - k);
    const std::uint64_t node = (std::uint64_t{1} << k) | above;
    scrambled ^= static_cast<std::uint32_t>(scramble_bit(seed, node)) << (31 - k);
  }
  return scrambled;
  // END EXERCISE 14.7
}

}  // namespace gi
