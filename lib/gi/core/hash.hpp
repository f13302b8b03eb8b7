#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace gi {

// FNV-1a, 64 bits: h = (h xor byte) * 1099511628211 from h = 14695981039346656037.
// A checksum against truncation and corruption and a short name for a long key; not
// a defence against someone who forges files on purpose.
inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 14695981039346656037ull) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

// 16 hexadecimal digits.
inline std::string hex(std::uint64_t value) {
  static const char digits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) text[i] = digits[value & 15];
  return text;
}

}  // namespace gi
