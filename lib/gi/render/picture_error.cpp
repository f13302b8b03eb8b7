#include "gi/radiosity/display/picture_error.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gi/radiosity/form_factors/form_factors.hpp"

namespace gi {

int BlockMask::count() const {
  int n = 0;
  for (char c : interior) n += c;
  return n;
}

BlockMask interior_blocks(const std::vector<Surface>& surfaces, const Camera& camera, int width, int height,
                          int block) {
  if (block < 1 || width % block != 0 || height % block != 0)
    throw std::invalid_argument("interior blocks: the block size " + std::to_string(block) +
                                " must divide the picture's " + std::to_string(width) + " x " +
                                std::to_string(height));
  // One polygon per surface: which surface an eye ray meets, whatever the mesh.
  const Mesh whole = make_mesh(surfaces, {});
  const FormFactorScene scene(element_shapes(whole));
  const CameraFrame frame = camera_frame(camera, width, height);
  // The surface seen through pixel (x, y)'s centre; -1 for the void, the back of a
  // surface or a light.
  const auto seen = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= width || y >= height) return -1;
    const auto hit = scene.first_hit(primary_ray(frame, x + 0.5, y + 0.5));
    if (!hit || !hit->front) return -1;
    const int surface = whole.elements[hit->polygon].surface;
    return max_component(surfaces[surface].emission) > 0 ? -1 : surface;
  };
  BlockMask mask{block, width / block, height / block, {}};
  mask.interior.assign(static_cast<std::size_t>(mask.blocks_x) * mask.blocks_y, 0);
  for (int by = 0; by < mask.blocks_y; ++by)
    for (int bx = 0; bx < mask.blocks_x; ++bx) {
      const int first = seen(bx * block, by * block);
      bool same = first >= 0;
      for (int y = by * block - 1; same && y <= (by + 1) * block; ++y)
        for (int x = bx * block - 1; same && x <= (bx + 1) * block; ++x) same = seen(x, y) == first;
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

// The mean of a block of pixels (or of their squares), per channel.
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

}  // namespace gi
