#pragma once
#include <vector>

#include "gi/core/math.hpp"
#include "gi/image/image.hpp"

namespace gi {

// Scoring a picture against a picture of the same scene and camera by another method
// (the truth), where the two can fairly agree. The picture is cut into blocks of
// block x block pixels; a block counts ("interior") when the pixels of the block and of
// the ring of pixels around it all see the same thing -- one surface, say, that is not a
// light. So every edge, corner and silhouette (where a pixel mixes surfaces, and a
// mesh's element boundary cannot follow) is left out, and each block's mean is a mean
// over one smooth surface. What a pixel sees is the method's to say (surface_mask.hpp,
// picture_mask.hpp): here an id per pixel centre, -1 for what no block may touch.
struct BlockMask {
  int block = 8;
  int blocks_x = 0, blocks_y = 0;
  std::vector<char> interior;  // blocks_x * blocks_y, row-major, 1 = counts
  int count() const;
};

// The blocks whose pixels and ring (outside the picture counts as -1) all see one id
// other than -1. `seen` holds width * height ids, row-major. Throws
// std::invalid_argument unless block divides width and height and there is one id a pixel.
BlockMask interior_blocks(const std::vector<int>& seen, int width, int height, int block);

// Two measures of how far a test picture is from the reference, both over the mask's
// blocks and the three channels, with t_bc and r_bc the block means:
//   relative RMS    e = sqrt( sum (t_bc - r_bc)^2 / sum r_bc^2 )
//                   the picture's error in proportion to its light: a dark corner
//                   counts for as little light as it holds
//   block relative  e = sqrt( mean ((t_bc - r_bc) / r_bc)^2 )
//                   every block and channel counts alike: a shadow twice too bright
//                   weighs as much as a bright wall twice too bright
// Both throw std::invalid_argument for pictures of another size than the mask's, an
// empty mask or (block relative) a reference block that is not positive.
struct PictureError {
  double relative_rms = 0;
  double block_relative = 0;
};
PictureError picture_error(const Image& test, const Image& reference, const BlockMask& mask);

// The noise of a picture by the same measures, from its per-pixel standard errors: a
// block's standard error is sqrt(sum se^2) / block^2 (independent pixels), in place of
// t_bc - r_bc. A test picture equal to the truth would still score about the truth's.
PictureError reference_noise(const Image& standard_error, const Image& reference, const BlockMask& mask);

// Each block x block block's mean, and (of a picture of standard errors) the standard
// error of that mean, sqrt(sum se^2) / block^2. Throws std::invalid_argument unless the
// block divides the picture's width and height.
Image block_means(const Image& image, int block);
Image block_standard_errors(const Image& standard_error, int block);

// Relative RMS difference sqrt(mean((t - r)^2 / r^2)) over pixels and channels, after
// averaging both pictures over blocks of block x block pixels (block 1: per pixel).
// Values whose reference is below 1e-3 of the reference's mean are left out (black
// corners would divide by zero). Throws std::invalid_argument for different sizes.
double relative_rms_error(const Image& test, const Image& reference, int block = 1);

// The same measure of a picture's own noise: sqrt(mean(se^2 / r^2)) over the blocks.
double relative_standard_error(const Image& standard_error, const Image& mean, int block = 1);

}  // namespace gi
