#include "gi/scene/cornell_box.hpp"

#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace gi {

// The data lives one floor down (gi/scene/cornell_box.hpp), where the path tracer
// reads it too; radiosity takes its surfaces as they are.
RadiosityScene cornell_box(bool closed) {
  const CornellBox box = cornell_box_data(CornellContents::Blocks, closed);
  RadiosityScene s;
  s.name = "cornell";
  for (const QuadSurface& q : box.surfaces) s.surfaces.push_back({q.name, q.corners, q.reflectance, q.exitance});
  s.camera = box.camera;
  return s;
}

}  // namespace gi
