#pragma once
#include "gi/image/image.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// A segment of the scene drawn over a picture the camera took: dots a quarter of a
// pixel apart along it, each put where image_position puts its point, so the segment
// follows the picture's perspective; points behind the eye and outside the picture
// are left out. For outlines and links drawn over a lesson's pictures (a BVH's boxes,
// the links that light one leaf).
void draw_segment(Image& picture, const CameraFrame& frame, const vec3& a, const vec3& b, Pixel colour);

}  // namespace gi
