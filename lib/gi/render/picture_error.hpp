#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// Scoring a radiosity picture against a picture of the same scene and camera by
// another renderer (a converged path-traced reference), where the two can fairly
// agree. The picture is cut into blocks of block x block pixels; a block counts
// ("interior") when the eye rays through the centres of its pixels and of the ring of
// pixels around it all meet the same surface, and that surface is not a light. So
// every edge, corner and silhouette (where a pixel mixes surfaces, and a mesh's
// element boundary cannot follow) and the light (whose radiance is given, not
// computed, and 20x the rest) are left out, and each block's mean is a mean over one
// smooth surface.
struct BlockMask {
  int block = 8;
  int blocks_x = 0, blocks_y = 0;
  std::vector<char> interior;  // blocks_x * blocks_y, row-major, 1 = counts
  int count() const;
};

// Throws std::invalid_argument unless block divides width and height.
BlockMask interior_blocks(const std::vector<Surface>& surfaces, const Camera& camera, int width, int height,
                          int block);

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

// The reference's own noise by the same measures, from its per-pixel standard errors:
// a block's standard error is sqrt(sum se^2) / block^2 (independent pixels), in place
// of t_bc - r_bc. A test picture equal to the truth would still score about this.
PictureError reference_noise(const Image& standard_error, const Image& reference, const BlockMask& mask);

}  // namespace gi
