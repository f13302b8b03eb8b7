#pragma once
// HMAC-SHA256 (RFC 2104 over FIPS 180-4's SHA-256): the graded test programs sign
// each verdict they report to the grader with a key only the grader and the test
// program's own harness hold (see graded_main.cpp), so that text written by the code
// under test -- to a file, to stdout, to every open descriptor -- is never taken for
// a verdict. The buffers a call makes from the key -- the padded key, the padded
// blocks, the hash states, the message schedule -- are overwritten before it returns
// (what the compiler keeps in registers or spills for a moment is beyond C++'s reach).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace support {

using Digest = std::array<std::uint8_t, 32>;

Digest sha256(std::string_view message);

// HMAC(K, m) = H((K' ^ opad) || H((K' ^ ipad) || m)), K' the key padded to 64 bytes.
Digest hmac_sha256(std::string_view key, std::string_view message);

std::string hex(const Digest& digest);

}  // namespace support
