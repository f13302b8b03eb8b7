#include "gi/image/diff.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gi {

namespace {

// Piecewise-linear colour ramp through black, blue, green, yellow and red.
Pixel ramp(double v) {
  const auto& stops = false_colour_stops;
  const double x = std::clamp(v, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(x));
  const float f = static_cast<float>(x - i);
  return (1.0f - f) * stops[i] + f * stops[i + 1];
}

// |a - b| per pixel, the mean over the channels.
std::vector<double> differences(const Image& a, const Image& b) {
  if (!a.same_size(b)) throw std::invalid_argument("difference_image: the images must have the same size");
  std::vector<double> diff(a.pixels.size());
  for (std::size_t i = 0; i < diff.size(); ++i) {
    const Pixel d = glm::abs(a.pixels[i] - b.pixels[i]);
    diff[i] = (double(d.x) + d.y + d.z) / 3.0;
  }
  return diff;
}

}  // namespace

Image false_colour(const std::vector<double>& values, int width, int height, double lo, double hi) {
  Image image(width, height);
  if (values.size() != image.pixels.size()) throw std::invalid_argument("false_colour: one value per pixel needed");
  const double range = hi > lo ? hi - lo : 1.0;
  for (std::size_t i = 0; i < values.size(); ++i) image.pixels[i] = ramp((values[i] - lo) / range);
  return image;
}

Image difference_image(const Image& a, const Image& b, double scale) {
  const std::vector<double> diff = differences(a, b);
  if (scale <= 0) scale = *std::max_element(diff.begin(), diff.end());
  return false_colour(diff, a.width, a.height, 0.0, scale > 0 ? scale : 1.0);
}

double largest_difference(const Image& a, const Image& b) {
  const std::vector<double> diff = differences(a, b);
  return diff.empty() ? 0.0 : *std::max_element(diff.begin(), diff.end());
}

Image crop(const Image& image, int x, int y, int w, int h) {
  if (x < 0 || y < 0 || w <= 0 || h <= 0 || x + w > image.width || y + h > image.height)
    throw std::invalid_argument("crop: the rectangle lies outside the image");
  Image out(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) out.at(i, j) = image.at(x + i, y + j);
  return out;
}

Image enlarge(const Image& image, int factor) {
  if (factor < 1) throw std::invalid_argument("enlarge: the factor must be at least 1");
  Image out(image.width * factor, image.height * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = image.at(x / factor, y / factor);
  return out;
}

Image side_by_side(const std::vector<Image>& images, int gap, Pixel gap_colour) {
  if (images.empty()) throw std::invalid_argument("side_by_side: no images");
  int width = -gap, height = 0;
  for (const Image& image : images) width += image.width + gap, height = std::max(height, image.height);
  Image out(width, height, gap_colour);
  int x0 = 0;
  for (const Image& image : images) {
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) out.at(x0 + x, y) = image.at(x, y);
    x0 += image.width + gap;
  }
  return out;
}

Image image_grid(const std::vector<Image>& images, int columns, int gap, Pixel gap_colour) {
  if (images.empty()) throw std::invalid_argument("image_grid: no images");
  if (columns < 1) throw std::invalid_argument("image_grid: fewer than one column");
  std::vector<Image> rows;
  for (std::size_t first = 0; first < images.size(); first += columns) {
    const std::size_t last = std::min(images.size(), first + columns);
    rows.push_back(side_by_side({images.begin() + first, images.begin() + last}, gap, gap_colour));
  }
  int width = 0, height = -gap;
  for (const Image& row : rows) width = std::max(width, row.width), height += row.height + gap;
  Image out(width, height, gap_colour);
  int y0 = 0;
  for (const Image& row : rows) {
    for (int y = 0; y < row.height; ++y)
      for (int x = 0; x < row.width; ++x) out.at(x, y0 + y) = row.at(x, y);
    y0 += row.height + gap;
  }
  return out;
}

}  // namespace gi
