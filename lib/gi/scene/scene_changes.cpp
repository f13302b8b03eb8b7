#include "gi/scene/scene_changes.hpp"

namespace gi {

Camera changed_camera(const Camera& camera, const CameraChange& change) {
  Camera c = camera;
  c.eye = change.eye;
  c.look_at = change.look_at;
  if (change.fov) c.vertical_fov = *change.fov;
  const vec3 view = c.look_at - c.eye;
  if (length(view) > 0 && length(cross(normalize(view), normalize(c.up))) < 1e-6) c.up = vec3(0, 0, 1);
  (void)camera_frame(c, 1, 1);  // throws for a degenerate camera
  return c;
}

}  // namespace gi
