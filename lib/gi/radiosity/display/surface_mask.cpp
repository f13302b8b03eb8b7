#include "gi/radiosity/display/surface_mask.hpp"

#include "gi/radiosity/form_factors/form_factors.hpp"

namespace gi {

BlockMask interior_blocks(const std::vector<Surface>& surfaces, const Camera& camera, int width, int height,
                          int block) {
  // One polygon per surface: which surface an eye ray meets, whatever the mesh.
  const Mesh whole = make_mesh(surfaces, {});
  const FormFactorScene scene(element_shapes(whole));
  const CameraFrame frame = camera_frame(camera, width, height);
  // The surface seen through each pixel's centre; -1 for the void, the back of a
  // surface or a light.
  std::vector<int> seen(static_cast<std::size_t>(width) * height, -1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto hit = scene.first_hit(primary_ray(frame, x + 0.5, y + 0.5));
      if (!hit || !hit->front) continue;
      const int surface = whole.elements[hit->polygon].surface;
      if (max_component(surfaces[surface].emission) <= 0) seen[static_cast<std::size_t>(y) * width + x] = surface;
    }
  return interior_blocks(seen, width, height, block);
}

}  // namespace gi
