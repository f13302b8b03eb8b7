#include "gi/radiosity/hierarchical/mesh_lines.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"

namespace gi {

std::vector<int> visible_polygons(const FormFactorScene& scene, const Camera& camera, int width, int height,
                                  int threads) {
  const CameraFrame frame = camera_frame(camera, width, height);
  std::vector<int> ids(static_cast<std::size_t>(width) * height, -1);
  parallel_for(height, threads, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const auto hit = scene.first_hit(primary_ray(frame, x + 0.5, y + 0.5));
      if (hit && hit->front) ids[static_cast<std::size_t>(y) * width + x] = hit->polygon;
    }
  });
  return ids;
}

Image draw_mesh_lines(const Image& picture, const std::vector<int>& ids, const Color& line, double opacity) {
  const int w = picture.width, h = picture.height;
  if (ids.size() != static_cast<std::size_t>(w) * h) throw std::invalid_argument("mesh lines: one id per pixel");
  Image out = picture;
  const auto id = [&](int x, int y) { return ids[static_cast<std::size_t>(y) * w + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool edge = (x + 1 < w && id(x + 1, y) != id(x, y)) || (y + 1 < h && id(x, y + 1) != id(x, y));
      if (edge) out.at(x, y) = Pixel((1 - opacity) * Color(out.at(x, y)) + opacity * line);
    }
  return out;
}

}  // namespace gi
