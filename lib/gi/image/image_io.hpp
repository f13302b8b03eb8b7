#pragma once
#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>

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

// Every writer creates parent folders and writes atomically (gi/core/atomic_file.hpp):
// the file appears whole or not at all. Each throws std::runtime_error naming the
// file (WriteError if the disk is full or the folder not writable).
// Every reader checks the size the file's header claims against the file's actual
// size before allocating, and throws std::runtime_error naming the file.

// PNG, sRGB-encoded, 8 bits per channel. Refuses (throws) an image with a NaN or
// infinite pixel: a garbage image is never written silently.
void write_png(const Image& image, const std::filesystem::path& file, double exposure = 1.0,
               ToneMap tone_map = ToneMap::Clamp);
// The same PNG's bytes, for a picture set inside another file (an SVG's data URL).
std::string encode_png(const Image& image, double exposure = 1.0, ToneMap tone_map = ToneMap::Clamp);

// Radiance HDR (RGBE), linear, no tone mapping: the values themselves.
void write_hdr(const Image& image, const std::filesystem::path& file);
Image read_hdr(const std::filesystem::path& file);
Image read_png(const std::filesystem::path& file);  // decoded back to linear

// Portable Float Map: the exact float values, for cached reference images that
// later errors are measured against (RGBE's 1% steps would floor those errors).
// Linear, never clamped: the pictures an outside renderer is compared with.
void write_pfm(const Image& image, const std::filesystem::path& file);
Image read_pfm(const std::filesystem::path& file);  // the file's size must match its header exactly

// The header "PF <width> <height> <scale>" read from `in`, which is left at the first
// pixel byte; `bytes` is the header's length. Throws std::runtime_error (naming
// `name`) for anything but a little-endian RGB PFM of sides in [1, max_image_side].
struct PfmHeader {
  int width = 0, height = 0;
  std::uintmax_t bytes = 0;
};
PfmHeader read_pfm_header(std::istream& in, const std::string& name);

}  // namespace gi
