#pragma once
#include <cstdint>
#include <filesystem>

#include "gi/image/image.hpp"

namespace gi {

// How linear radiance becomes a displayable value in [0, 1] before sRGB encoding:
//   Clamp     c * exposure, clamped (what the lecture's Phong images assume)
//   Reinhard  x / (1 + x) per channel of x = c * exposure (bright areas keep detail)
enum class ToneMap { Clamp, Reinhard };

// The sRGB transfer curve: encode(c) = 12.92 c for c <= 0.0031308, else
// 1.055 c^(1/2.4) - 0.055; decode is its inverse.
double srgb_encode(double linear);
double srgb_decode(double encoded);
std::uint8_t to_srgb8(float linear);  // round(255 encode(clamp(c, 0, 1)))
float from_srgb8(std::uint8_t encoded);

// PNG, sRGB-encoded, 8 bits per channel. Creates parent folders. Throws
// std::runtime_error naming the file if it cannot be written or if a pixel is NaN
// or infinite (a garbage image is never written silently).
void write_png(const Image& image, const std::filesystem::path& file, double exposure = 1.0,
               ToneMap tone_map = ToneMap::Clamp);

// Radiance HDR (RGBE), linear, no tone mapping: the values themselves.
void write_hdr(const Image& image, const std::filesystem::path& file);
Image read_hdr(const std::filesystem::path& file);
Image read_png(const std::filesystem::path& file);  // decoded back to linear

// Portable Float Map: the exact float values, for cached reference images that
// later errors are measured against (RGBE's 1% steps would floor those errors).
void write_pfm(const Image& image, const std::filesystem::path& file);
Image read_pfm(const std::filesystem::path& file);  // throws std::runtime_error if malformed

}  // namespace gi
