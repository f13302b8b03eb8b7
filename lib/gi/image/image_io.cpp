#include "gi/image/image_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "gi/core/atomic_file.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

namespace gi {

namespace {

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

namespace {

// stb hands the encoded bytes to this callback, which passes them to the stream of
// an AtomicFile: the picture appears whole under its name, or not at all.
void to_stream(void* context, void* data, int size) {
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

}  // namespace

namespace {

// The image's PNG bytes into `out`; false if stb could not encode them.
bool png_to(std::ostream& out, const Image& image, double exposure, ToneMap mapping) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixels.size() * 3);
  for (const Pixel& p : image.pixels)
    for (int c = 0; c < 3; ++c) bytes.push_back(to_srgb8(tone_map(p[c], exposure, mapping)));
  // The "Sub" row filter for every row: rendered images compress about as well as
  // with stb's per-row choice among all five filters, at two thirds of the time.
  stbi_write_force_png_filter = 1;
  return stbi_write_png_to_func(to_stream, &out, image.width, image.height, 3, bytes.data(), image.width * 3) != 0;
}

}  // namespace

void write_png(const Image& image, const std::filesystem::path& file, double exposure, ToneMap mapping) {
  check_finite(image, file);
  write_atomically(file, [&](std::ostream& out) {
    if (!png_to(out, image, exposure, mapping)) throw WriteError("cannot encode " + file.string() + " as PNG");
  });
}

std::string encode_png(const Image& image, double exposure, ToneMap mapping) {
  check_finite(image, "a picture to encode");
  std::ostringstream out;
  if (!png_to(out, image, exposure, mapping)) throw std::runtime_error("cannot encode a picture as PNG");
  return out.str();
}

void write_hdr(const Image& image, const std::filesystem::path& file) {
  check_finite(image, file);
  write_atomically(file, [&](std::ostream& out) {
    if (!stbi_write_hdr_to_func(to_stream, &out, image.width, image.height, 3, &image.pixels[0].x))
      throw WriteError("cannot encode " + file.string() + " as HDR");
  });
}

namespace {

// The whole file, or std::runtime_error naming it.
std::string file_bytes(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) throw std::runtime_error("cannot read " + file.string() + ": " + error.message());
  std::ifstream in(file, std::ios::binary);
  std::string bytes(size, '\0');  // bounded by the file's real size
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (!in || in.gcount() != static_cast<std::streamsize>(size)) throw std::runtime_error("cannot read " + file.string());
  return bytes;
}

// Decodes a PNG or HDR file with stb after checking the size its header claims:
// no format can hold more pixels than `max_pixels_per_byte` per byte of file (deflate
// expands at most 1032-fold; RGBE run-lengths give 127 pixels for 8 bytes), so a
// header that claims more is lying and is refused before anything is allocated.
template <class T, class Load, class Convert>
Image decode(const std::filesystem::path& file, const char* format, double max_pixels_per_byte, Load load,
             Convert convert) {
  const std::string bytes = file_bytes(file);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(std::min<std::size_t>(bytes.size(), std::numeric_limits<int>::max()));
  int w = 0, h = 0, channels = 0;
  if (bytes.size() != static_cast<std::size_t>(length) || !stbi_info_from_memory(data, length, &w, &h, &channels))
    throw std::runtime_error(file.string() + " is not a " + format + " file this reader knows (" +
                             stbi_failure_reason() + ")");
  if (w <= 0 || h <= 0 || w > max_image_side || h > max_image_side ||
      double(w) * h > max_pixels_per_byte * double(bytes.size()))
    throw std::runtime_error(file.string() + ": its header claims " + std::to_string(w) + "x" + std::to_string(h) +
                             " pixels, more than " + std::to_string(bytes.size()) + " bytes can hold");
  std::unique_ptr<T, void (*)(void*)> pixels(load(data, length, &w, &h, &channels, 3), stbi_image_free);
  if (!pixels) throw std::runtime_error("cannot read " + file.string() + ": " + stbi_failure_reason());
  Image image(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = Pixel(convert(pixels.get()[3 * i]), convert(pixels.get()[3 * i + 1]), convert(pixels.get()[3 * i + 2]));
  return image;
}

}  // namespace

Image read_hdr(const std::filesystem::path& file) {
  return decode<float>(file, "Radiance HDR", 127.0 / 8, stbi_loadf_from_memory, [](float v) { return v; });
}

Image read_png(const std::filesystem::path& file) {
  return decode<stbi_uc>(file, "PNG", 1032.0, stbi_load_from_memory, [](stbi_uc v) { return from_srgb8(v); });
}

static_assert(sizeof(Pixel) == 3 * sizeof(float), "PFM stores pixels as three packed floats");

// PFM: "PF\n<width> <height>\n-1\n" (negative scale: little-endian), then float RGB
// rows from the bottom of the image up.
void write_pfm(const Image& image, const std::filesystem::path& file) {
  write_atomically(file, [&](std::ostream& out) {
    out << "PF\n" << image.width << ' ' << image.height << "\n-1\n";
    for (int y = image.height - 1; y >= 0; --y)
      out.write(reinterpret_cast<const char*>(&image.at(0, y)), sizeof(Pixel) * image.width);
  });
}

PfmHeader read_pfm_header(std::istream& in, const std::string& name) {
  // Four fields separated by white space, the last followed by exactly one
  // white-space character; a real header is a few dozen bytes, so reading stops
  // after 128 whatever the file holds.
  const auto field = [&](const char* what, bool first) {
    std::string text;
    int c = in.get();
    while (!first && c != EOF && std::isspace(c) && in.tellg() < 128) c = in.get();
    for (; c != EOF && !std::isspace(c) && text.size() <= 24; c = in.get()) text += static_cast<char>(c);
    if (text.empty() || text.size() > 24 || c == EOF) throw std::runtime_error(name + ": PFM header has no valid " + what);
    return text;
  };
  const std::string magic = in.peek() == 'P' ? field("magic number", true) : "";
  if (magic == "Pf") throw std::runtime_error(name + " is a greyscale PFM; only RGB (PF) is read");
  if (magic != "PF") throw std::runtime_error(name + " is not a PFM file (no PF at the start)");
  const auto side = [&](const char* what) {
    const std::string text = field(what, false);
    const bool digits = text.size() <= 5 && text.find_first_not_of("0123456789") == std::string::npos;
    const int value = digits ? std::stoi(text) : 0;
    if (value < 1 || value > max_image_side)
      throw std::runtime_error(name + ": PFM " + what + " must be a whole number in [1, " +
                               std::to_string(max_image_side) + "], got '" + text + "'");
    return value;
  };
  PfmHeader header;
  header.width = side("width");
  header.height = side("height");
  const std::string scale = field("scale", false);
  char* end = nullptr;
  const double s = std::strtod(scale.c_str(), &end);
  if (*end != '\0' || !std::isfinite(s) || s == 0)
    throw std::runtime_error(name + ": PFM scale '" + scale + "' is not a non-zero number");
  if (s > 0) throw std::runtime_error(name + " is a big-endian PFM; only little-endian (negative scale) is read");
  header.bytes = static_cast<std::uintmax_t>(in.tellg());
  return header;
}

Image read_pfm(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) throw std::runtime_error("cannot read " + file.string() + ": " + error.message());
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  const PfmHeader header = read_pfm_header(in, file.string());
  // Checked against the file's real size before the image is allocated: a short
  // file with a header claiming 30000 x 30000 pixels is refused, not given 10 GB.
  const std::uintmax_t pixels = std::uintmax_t(header.width) * header.height * sizeof(Pixel);
  if (size != header.bytes + pixels)
    throw std::runtime_error(file.string() + ": PFM header says " + std::to_string(header.width) + "x" +
                             std::to_string(header.height) + " (" + std::to_string(header.bytes + pixels) +
                             " bytes), the file has " + std::to_string(size) + (size < header.bytes + pixels ? " (truncated)" : ""));
  Image image(header.width, header.height);
  for (int y = header.height - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(&image.at(0, y)), static_cast<std::streamsize>(sizeof(Pixel)) * header.width);
  if (!in) throw std::runtime_error(file.string() + " is truncated");
  return image;
}

}  // namespace gi
