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

// The point's direction d from the eye meets the image plane (distance 1 along the
// view direction f = right x down) at d / (d . f); its offsets from the top-left
// corner along right and down, over their lengths, are x and y.
std::optional<glm::dvec2> image_position(const CameraFrame& frame, const vec3& point) {
  const vec3 forward = normalize(cross(frame.right, frame.down));
  const vec3 d = point - frame.eye;
  const double depth = dot(d, forward);
  if (!(depth > 0)) return std::nullopt;
  const vec3 q = d / depth - frame.top_left;
  return glm::dvec2(dot(q, frame.right) / dot(frame.right, frame.right), dot(q, frame.down) / dot(frame.down, frame.down));
}

}  // namespace gi
