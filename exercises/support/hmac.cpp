#include "support/hmac.hpp"

#include <cstddef>

namespace support {
namespace {

// The first 32 bits of the fractional parts of the cube roots of the first 64 primes.
constexpr std::uint32_t round_constants[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

constexpr std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

// Overwrites memory that held key material, in a way the compiler may not leave out:
// a block freed or a stack frame left must not hand the key to code that allocates
// or declares the same memory next (an uninitialised read in the code under test).
void wipe(void* memory, std::size_t size) {
  volatile std::uint8_t* bytes = static_cast<volatile std::uint8_t*>(memory);
  for (std::size_t k = 0; k < size; ++k) bytes[k] = 0;
}

// One 64-byte block into the state h (FIPS 180-4, section 6.2.2).
void compress(std::uint32_t h[8], const std::uint8_t* block) {
  std::uint32_t w[64];
  for (int t = 0; t < 16; ++t)
    w[t] = std::uint32_t(block[4 * t]) << 24 | std::uint32_t(block[4 * t + 1]) << 16 |
           std::uint32_t(block[4 * t + 2]) << 8 | std::uint32_t(block[4 * t + 3]);
  for (int t = 16; t < 64; ++t) {
    const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
    const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
    w[t] = w[t - 16] + s0 + w[t - 7] + s1;
  }
  std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], k = h[7];
  for (int t = 0; t < 64; ++t) {
    const std::uint32_t t1 = k + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + round_constants[t] + w[t];
    const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    k = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
  }
  h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e, h[5] += f, h[6] += g, h[7] += k;
  wipe(w, sizeof w);
}

// SHA-256 fed piece by piece, so that HMAC never copies the key into a string of its own.
class Sha256 {
 public:
  ~Sha256() { wipe(h_, sizeof h_), wipe(block_, sizeof block_); }

  void add(const std::uint8_t* data, std::size_t size) {
    length_ += size;
    for (std::size_t k = 0; k < size; ++k) {
      block_[used_++] = data[k];
      if (used_ == 64) compress(h_, block_), used_ = 0;
    }
  }
  void add(std::string_view text) { add(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()); }

  // The message, a 1 bit, zeros to 56 mod 64 bytes, and its length in bits (big-endian).
  Digest finish() {
    const std::uint64_t bits = length_ * 8;
    const std::uint8_t one = 0x80, zero = 0;
    add(&one, 1);
    while (used_ != 56) add(&zero, 1);
    for (int k = 7; k >= 0; --k) {
      const std::uint8_t byte = std::uint8_t(bits >> (8 * k));
      add(&byte, 1);
    }
    Digest digest;
    for (int k = 0; k < 32; ++k) digest[k] = std::uint8_t(h_[k / 4] >> (24 - 8 * (k % 4)));
    return digest;
  }

 private:
  // The first 32 bits of the fractional parts of the square roots of the first 8 primes.
  std::uint32_t h_[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::uint8_t block_[64] = {};
  std::size_t used_ = 0;
  std::uint64_t length_ = 0;
};

}  // namespace

Digest sha256(std::string_view message) {
  Sha256 hash;
  hash.add(message);
  return hash.finish();
}

Digest hmac_sha256(std::string_view key, std::string_view message) {
  std::uint8_t padded[64] = {};  // K', wiped below with everything made from it
  if (key.size() > 64) {
    Digest hashed = sha256(key);
    for (int k = 0; k < 32; ++k) padded[k] = hashed[k];
    wipe(hashed.data(), hashed.size());
  } else {
    for (std::size_t k = 0; k < key.size(); ++k) padded[k] = std::uint8_t(key[k]);
  }
  std::uint8_t pad[64];
  Sha256 inner, outer;
  for (int k = 0; k < 64; ++k) pad[k] = padded[k] ^ 0x36;
  inner.add(pad, 64);
  inner.add(message);
  Digest inner_hash = inner.finish();
  for (int k = 0; k < 64; ++k) pad[k] = padded[k] ^ 0x5c;
  outer.add(pad, 64);
  outer.add(inner_hash.data(), inner_hash.size());
  wipe(padded, sizeof padded), wipe(pad, sizeof pad), wipe(inner_hash.data(), inner_hash.size());
  return outer.finish();
}

std::string hex(const Digest& digest) {
  static const char digits[] = "0123456789abcdef";
  std::string text;
  for (std::uint8_t byte : digest) text += digits[byte >> 4], text += digits[byte & 15];
  return text;
}

}  // namespace support
