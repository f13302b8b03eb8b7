#include "gi/accel/ray_sets.hpp"

#include <cmath>

#include "gi/scene/camera.hpp"

namespace gi {

std::vector<Ray> camera_rays(const Scene& scene, int width, int height, int stride) {
  const CameraFrame frame = camera_frame(scene.camera, width, height);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(width) * height / stride + 1);
  for (long long p = 0; p < static_cast<long long>(width) * height; p += stride)
    rays.push_back(primary_ray(frame, p % width + 0.5, p / width + 0.5));
  return rays;
}

std::vector<Ray> random_rays(const Aabb& region, int count, Rng& rng) {
  std::vector<Ray> rays;
  rays.reserve(count);
  for (int k = 0; k < count; ++k) {
    vec3 origin;
    for (int axis = 0; axis < 3; ++axis) origin[axis] = region.lo[axis] + rng.uniform() * (region.hi[axis] - region.lo[axis]);
    const double z = 1 - 2 * rng.uniform(), phi = 2 * pi * rng.uniform();  // uniform on the sphere
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    rays.push_back({origin, {r * std::cos(phi), r * std::sin(phi), z}});
  }
  return rays;
}

}  // namespace gi
