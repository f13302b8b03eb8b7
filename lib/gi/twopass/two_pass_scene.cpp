#include "gi/twopass/two_pass_scene.hpp"

#include <stdexcept>

#include "gi/scene/cornell_box.hpp"

namespace gi {

std::vector<std::string> two_pass_scene_names() { return {"cornell", "cornell-spheres"}; }

TwoPassScene make_two_pass_scene(const std::string& name) {
  if (name != "cornell" && name != "cornell-spheres")
    throw std::invalid_argument("unknown scene '" + name + "' (two-pass scenes: cornell, cornell-spheres)");
  const CornellBox box = cornell_box_data(name == "cornell" ? CornellContents::Blocks : CornellContents::Spheres);
  TwoPassScene s;
  s.name = name;
  for (const QuadSurface& q : box.surfaces) s.surfaces.push_back({q.name, q.corners, q.reflectance, q.exitance});
  // The spheres' materials exactly as the path tracer's scene has them, so that the
  // reference and the two-pass picture show the same mirror and the same glass.
  const Scene traced = cornell_box_scene(box);
  for (const Sphere& sphere : traced.spheres) s.spheres.push_back({sphere, traced.materials[sphere.material]});
  s.camera = box.camera;
  return s;
}

}  // namespace gi
