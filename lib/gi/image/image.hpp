#pragma once
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

namespace gi {

using Pixel = glm::vec3;  // stored images are float linear RGB

// The largest width or height of an image: 32768 (a 12 GB float image at most).
constexpr int max_image_side = 1 << 15;

// A linear-RGB image, row 0 at the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Pixel> pixels;  // row-major

  Image() = default;
  Image(int w, int h, Pixel fill = Pixel(0)) : width(w), height(h) {
    if (w <= 0 || h <= 0 || w > max_image_side || h > max_image_side)
      throw std::invalid_argument("image: width and height must lie in [1, 32768]");
    pixels.assign(static_cast<std::size_t>(w) * h, fill);
  }

  Pixel& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Pixel& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  bool same_size(const Image& other) const { return width == other.width && height == other.height; }
};

}  // namespace gi
