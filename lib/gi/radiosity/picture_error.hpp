#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/mesh.hpp"
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

// The relative RMS error over the mask's blocks and the three channels:
//   e = sqrt( mean over blocks b, channels c of ((t_bc - r_bc) / r_bc)^2 )
// with t_bc, r_bc the block means of test and reference. Throws std::invalid_argument
// for pictures of another size than the mask's, an empty mask or a reference block
// that is not positive.
double block_relative_rms(const Image& test, const Image& reference, const BlockMask& mask);

// The reference's own noise by the same measure, from its per-pixel standard errors:
// a block's standard error is sqrt(sum se^2) / block^2 (independent pixels), and
//   sqrt( mean over blocks and channels of (se_bc / r_bc)^2 ).
// A test picture equal to the truth would still score about this.
double block_relative_noise(const Image& standard_error, const Image& reference, const BlockMask& mask);

}  // namespace gi
