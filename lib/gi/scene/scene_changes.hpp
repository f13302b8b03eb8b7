#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gi/scene/camera.hpp"

namespace gi {

// What the radiosity lessons' command line changes in a scene without editing it:
// radiosity is view-independent, so a new viewpoint shows the same solution
// (--camera), and a light's emission only changes E, so a brighter or dimmer light
// keeps the form factors (--light-scale).

// A new viewpoint: where the eye is, what it looks at, and (if given) the vertical
// field of view in degrees.
struct CameraChange {
  vec3 eye;
  vec3 look_at;
  std::optional<double> fov;
};

// The emission of every surface named `light` times `factor` (0 turns it off).
struct LightScale {
  std::string light;
  double factor = 1;
};

struct SceneChanges {
  std::optional<CameraChange> camera;
  std::vector<LightScale> light_scales;
};

// The camera moved: `up` stays the scene's unless the new view runs along it (a view
// from straight above), when it becomes +z. Throws std::invalid_argument for a
// degenerate camera (camera_frame's checks).
Camera changed_camera(const Camera& camera, const CameraChange& change);

}  // namespace gi
