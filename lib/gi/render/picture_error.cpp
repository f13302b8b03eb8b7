#include "gi/render/picture_error.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gi {

int BlockMask::count() const {
  int n = 0;
  for (char c : interior) n += c;
  return n;
}

BlockMask interior_blocks(const std::vector<int>& seen, int width, int height, int block) {
  if (block < 1 || width % block != 0 || height % block != 0)
    throw std::invalid_argument("interior blocks: the block size " + std::to_string(block) +
                                " must divide the picture's " + std::to_string(width) + " x " +
                                std::to_string(height));
  if (seen.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("interior blocks: one id per pixel");
  const auto at = [&](int x, int y) {
    return x < 0 || y < 0 || x >= width || y >= height ? -1 : seen[static_cast<std::size_t>(y) * width + x];
  };
  BlockMask mask{block, width / block, height / block, {}};
  mask.interior.assign(static_cast<std::size_t>(mask.blocks_x) * mask.blocks_y, 0);
  for (int by = 0; by < mask.blocks_y; ++by)
    for (int bx = 0; bx < mask.blocks_x; ++bx) {
      const int first = at(bx * block, by * block);
      bool same = first >= 0;
      for (int y = by * block - 1; same && y <= (by + 1) * block; ++y)
        for (int x = bx * block - 1; same && x <= (bx + 1) * block; ++x) same = at(x, y) == first;
      mask.interior[by * mask.blocks_x + bx] = same;
    }
  return mask;
}

namespace {

void check_sizes(const Image& a, const Image& b, const BlockMask& mask, const char* what) {
  if (a.width != mask.blocks_x * mask.block || a.height != mask.blocks_y * mask.block || !a.same_size(b))
    throw std::invalid_argument(std::string(what) + ": the pictures must both be the mask's size");
  if (mask.count() == 0) throw std::invalid_argument(std::string(what) + ": the mask keeps no block");
}

void check_block(const Image& image, int block) {
  if (block < 1 || image.width % block || image.height % block)
    throw std::invalid_argument("the block size must divide the image's width and height");
}

// The sum over a block of pixels (or of their squares), per channel.
Color block_sum(const Image& image, int bx, int by, int block, bool squares) {
  Color sum(0.0);
  for (int y = by * block; y < (by + 1) * block; ++y)
    for (int x = bx * block; x < (bx + 1) * block; ++x) {
      const Color p(image.at(x, y));
      sum += squares ? p * p : p;
    }
  return sum;
}

// Both measures, with `difference`(bx, by) in place of t_b - r_b.
template <class Difference>
PictureError measure(const Image& reference, const BlockMask& mask, const char* what, Difference difference) {
  const double pixels = double(mask.block) * mask.block;
  double squared = 0, reference_squared = 0, relative_squared = 0;
  int n = 0;
  for (int by = 0; by < mask.blocks_y; ++by)
    for (int bx = 0; bx < mask.blocks_x; ++bx) {
      if (!mask.interior[by * mask.blocks_x + bx]) continue;
      const Color r = block_sum(reference, bx, by, mask.block, false) / pixels;
      const Color e = difference(bx, by);
      for (int c = 0; c < 3; ++c) {
        if (!(r[c] > 0)) throw std::invalid_argument(std::string(what) + ": a reference block is not positive");
        squared += e[c] * e[c], reference_squared += r[c] * r[c];
        relative_squared += (e[c] / r[c]) * (e[c] / r[c]);
        ++n;
      }
    }
  return {std::sqrt(squared / reference_squared), std::sqrt(relative_squared / n)};
}

// sqrt(mean over values with r above the cut of (a / r)^2).
double relative_rms(const Image& a, const Image& r) {
  double total = 0;
  for (const Pixel& p : r.pixels) total += (double(p.x) + p.y + p.z) / 3;
  const double cut = 1e-3 * total / double(r.pixels.size());  // 1e-3 of the mean
  double sum = 0;
  long long count = 0;
  for (std::size_t i = 0; i < r.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (r.pixels[i][c] > cut) {
        const double q = double(a.pixels[i][c]) / r.pixels[i][c];
        sum += q * q;
        ++count;
      }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

// Each block's mean, or (squares) the root of its squares' sum over the block's area.
Image over_blocks(const Image& image, int block, bool errors) {
  check_block(image, block);
  Image out(image.width / block, image.height / block);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const Color sum = block_sum(image, x, y, block, errors);
      out.at(x, y) = Pixel((errors ? glm::sqrt(sum) : sum) / double(block * block));
    }
  return out;
}

}  // namespace

PictureError picture_error(const Image& test, const Image& reference, const BlockMask& mask) {
  check_sizes(test, reference, mask, "picture error");
  const double pixels = double(mask.block) * mask.block;
  return measure(reference, mask, "picture error", [&](int bx, int by) {
    return (block_sum(test, bx, by, mask.block, false) - block_sum(reference, bx, by, mask.block, false)) / pixels;
  });
}

PictureError reference_noise(const Image& standard_error, const Image& reference, const BlockMask& mask) {
  check_sizes(standard_error, reference, mask, "reference noise");
  const double pixels = double(mask.block) * mask.block;
  return measure(reference, mask, "reference noise", [&](int bx, int by) {
    return sqrt(block_sum(standard_error, bx, by, mask.block, true)) / pixels;
  });
}

Image block_means(const Image& image, int block) { return over_blocks(image, block, false); }

Image block_standard_errors(const Image& standard_error, int block) { return over_blocks(standard_error, block, true); }

double relative_rms_error(const Image& test, const Image& reference, int block) {
  if (!test.same_size(reference)) throw std::invalid_argument("relative RMS error: the images differ in size");
  const Image t = block_means(test, block), r = block_means(reference, block);
  Image difference(t.width, t.height);
  for (std::size_t i = 0; i < t.pixels.size(); ++i) difference.pixels[i] = t.pixels[i] - r.pixels[i];
  return relative_rms(difference, r);
}

double relative_standard_error(const Image& standard_error, const Image& mean, int block) {
  return relative_rms(block_standard_errors(standard_error, block), block_means(mean, block));
}

}  // namespace gi
