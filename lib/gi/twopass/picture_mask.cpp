#include "gi/twopass/picture_mask.hpp"

#include <algorithm>

#include "gi/geometry/sphere.hpp"

namespace gi {

BlockMask diffuse_interior_blocks(const TwoPassScene& scene, int width, int height, int block) {
  BlockMask mask = interior_blocks(scene.surfaces, scene.camera, width, height, block);
  const CameraFrame frame = camera_frame(scene.camera, width, height);
  for (int by = 0; by < mask.blocks_y; ++by)
    for (int bx = 0; bx < mask.blocks_x; ++bx) {
      char& counts = mask.interior[by * mask.blocks_x + bx];
      // The block's pixels and the ring around it, as interior_blocks looks at them.
      for (int y = std::max(0, by * block - 1); counts && y < std::min(height, (by + 1) * block + 1); ++y)
        for (int x = std::max(0, bx * block - 1); counts && x < std::min(width, (bx + 1) * block + 1); ++x)
          for (const SpecularSphere& s : scene.spheres)
            if (intersect(primary_ray(frame, x + 0.5, y + 0.5), s.shape)) counts = 0;
    }
  return mask;
}

}  // namespace gi
