#include "gi/image/image_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

namespace gi {

namespace {

void make_parent(const std::filesystem::path& file) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
}

void check_finite(const Image& image, const std::filesystem::path& file) {
  for (const Pixel& p : image.pixels)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::runtime_error("refusing to write " + file.string() + ": the image contains NaN or infinite pixels");
}

float tone_map(float c, double exposure, ToneMap mapping) {
  const double x = std::max(0.0, c * exposure);
  return static_cast<float>(mapping == ToneMap::Reinhard ? x / (1.0 + x) : std::min(1.0, x));
}

}  // namespace

double srgb_encode(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }
double srgb_decode(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }
float from_srgb8(std::uint8_t encoded) { return static_cast<float>(srgb_decode(encoded / 255.0)); }

namespace {

// boundary[k] is the linear value whose encoding is exactly (k + 0.5) / 255: values
// below it round to code k or less. Comparing against these boundaries gives the
// same code as rounding 255 * encode(c), without a pow() per channel. A coarse
// table of 4096 buckets says where to start; a step or two remains.
struct SrgbTable {
  std::array<double, 256> boundary{};
  std::array<std::uint8_t, 4097> first_code{};
  SrgbTable() {
    for (int k = 0; k < 255; ++k) boundary[k] = srgb_decode((k + 0.5) / 255.0);
    boundary[255] = std::numeric_limits<double>::infinity();
    int code = 0;
    for (int i = 0; i <= 4096; ++i) {
      while (i / 4096.0 >= boundary[code]) ++code;
      first_code[i] = static_cast<std::uint8_t>(code);
    }
  }
};
const SrgbTable srgb_table;

}  // namespace

std::uint8_t to_srgb8(float linear) {
  if (!(linear > 0)) return 0;  // also NaN
  if (linear >= 1) return 255;
  int code = srgb_table.first_code[static_cast<int>(linear * 4096.0f)];
  while (linear >= srgb_table.boundary[code]) ++code;
  while (code > 0 && linear < srgb_table.boundary[code - 1]) --code;  // float rounding put it a bucket too far
  return static_cast<std::uint8_t>(code);
}

void write_png(const Image& image, const std::filesystem::path& file, double exposure, ToneMap mapping) {
  check_finite(image, file);
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixels.size() * 3);
  for (const Pixel& p : image.pixels)
    for (int c = 0; c < 3; ++c) bytes.push_back(to_srgb8(tone_map(p[c], exposure, mapping)));
  make_parent(file);
  // The "Sub" row filter for every row: rendered images compress about as well as
  // with stb's per-row choice among all five filters, at two thirds of the time.
  stbi_write_force_png_filter = 1;
  if (!stbi_write_png(file.string().c_str(), image.width, image.height, 3, bytes.data(), image.width * 3))
    throw std::runtime_error("cannot write " + file.string());
}

void write_hdr(const Image& image, const std::filesystem::path& file) {
  check_finite(image, file);
  make_parent(file);
  if (!stbi_write_hdr(file.string().c_str(), image.width, image.height, 3, &image.pixels[0].x))
    throw std::runtime_error("cannot write " + file.string());
}

Image read_hdr(const std::filesystem::path& file) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(file.string().c_str(), &w, &h, &channels, 3),
                                               stbi_image_free);
  if (!data) throw std::runtime_error("cannot read " + file.string());
  Image image(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = Pixel(data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]);
  return image;
}

Image read_png(const std::filesystem::path& file) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load(file.string().c_str(), &w, &h, &channels, 3),
                                                       stbi_image_free);
  if (!data) throw std::runtime_error("cannot read " + file.string());
  Image image(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = Pixel(from_srgb8(data.get()[3 * i]), from_srgb8(data.get()[3 * i + 1]),
                            from_srgb8(data.get()[3 * i + 2]));
  return image;
}

static_assert(sizeof(Pixel) == 3 * sizeof(float), "PFM stores pixels as three packed floats");

// PFM: "PF\n<width> <height>\n-1\n" (negative scale: little-endian), then float RGB
// rows from the bottom of the image up.
void write_pfm(const Image& image, const std::filesystem::path& file) {
  make_parent(file);
  std::ofstream out(file, std::ios::binary);
  out << "PF\n" << image.width << ' ' << image.height << "\n-1\n";
  for (int y = image.height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(&image.at(0, y)), sizeof(Pixel) * image.width);
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

Image read_pfm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  int w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  in.get();  // the single white-space character before the data
  if (!in || magic != "PF" || scale >= 0) throw std::runtime_error(file.string() + " is not a little-endian RGB PFM");
  Image image(w, h);
  for (int y = h - 1; y >= 0; --y) in.read(reinterpret_cast<char*>(&image.at(0, y)), sizeof(Pixel) * w);
  if (!in) throw std::runtime_error(file.string() + " is truncated");
  return image;
}

}  // namespace gi
