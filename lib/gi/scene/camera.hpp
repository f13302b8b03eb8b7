#pragma once
#include <optional>

#include "gi/core/ray.hpp"

namespace gi {

// A pinhole camera: the eye looks at `look_at`, `up` says which way is up, and
// `vertical_fov` (degrees) is the angle from the image's top edge to its bottom.
struct Camera {
  vec3 eye{0, 0, 0};
  vec3 look_at{0, 0, -1};
  vec3 up{0, 1, 0};
  double vertical_fov = 45;
};

// The image plane set up for one image size: pixel (x, y) -- y grows downwards --
// is the point eye + top_left + x * right + y * down, at distance 1 in front of the eye.
struct CameraFrame {
  vec3 eye;
  vec3 top_left;  // the image's top-left corner, seen from the eye
  vec3 right;     // one pixel to the right
  vec3 down;      // one pixel down
};

// Throws std::invalid_argument for a degenerate camera (eye at look_at, up parallel
// to the view direction, field of view outside (0, 180)) or a non-positive size.
CameraFrame camera_frame(const Camera& camera, int width, int height);

// The eye ray through image position (x, y), in pixels: (x + 0.5, y + 0.5) is the
// centre of pixel (x, y). The direction is unit length.
Ray primary_ray(const CameraFrame& frame, double x, double y);

// Where a point appears in the image, in pixels (the inverse of primary_ray: the
// point's direction from the eye, scaled to the image plane), or nothing for a point
// not in front of the eye. For drawing a scene's lines over its picture.
std::optional<glm::dvec2> image_position(const CameraFrame& frame, const vec3& point);

}  // namespace gi
