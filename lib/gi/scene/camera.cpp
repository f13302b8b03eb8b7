#include "gi/scene/camera.hpp"

#include <stdexcept>

namespace gi {

CameraFrame camera_frame(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("camera: image size must be positive");
  if (!(camera.vertical_fov > 0 && camera.vertical_fov < 180))
    throw std::invalid_argument("camera: the field of view must lie in (0, 180) degrees");
  const vec3 view = camera.look_at - camera.eye;
  if (!is_finite(view) || length(view) == 0) throw std::invalid_argument("camera: eye and look_at must differ");
  const vec3 forward = normalize(view);
  const vec3 side = cross(forward, camera.up);
  if (length(side) < 1e-9) throw std::invalid_argument("camera: up must not be parallel to the view direction");

  const vec3 right_unit = normalize(side);
  const vec3 up_unit = cross(right_unit, forward);
  const double half_height = std::tan(0.5 * camera.vertical_fov * pi / 180.0);
  const double pixel = 2.0 * half_height / height;  // square pixels
  CameraFrame frame;
  frame.eye = camera.eye;
  frame.right = pixel * right_unit;
  frame.down = -pixel * up_unit;
  frame.top_left = forward - 0.5 * width * frame.right - 0.5 * height * frame.down;
  return frame;
}

// The image plane one unit in front of the eye, its points taken from the eye: added
// to the eye and subtracted again, a direction would lose the eye's digits (half of
// them at an eye 10^8 from the origin) and a scene in km would look at another
// picture than the same scene in m.
Ray primary_ray(const CameraFrame& frame, double x, double y) {
  return Ray{frame.eye, normalize(frame.top_left + x * frame.right + y * frame.down)};
}

}  // namespace gi
