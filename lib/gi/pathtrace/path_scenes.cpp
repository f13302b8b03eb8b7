#include "gi/pathtrace/path_scenes.hpp"

#include <stdexcept>

#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/cornell_box.hpp"

namespace gi {

namespace {

Material emitter(const std::string& name, const Color& radiance) {
  Material m;
  m.name = name;
  m.diffuse = Color(0.0);
  m.emission = radiance;
  return m;
}

bool same_shape(const Quad& a, const Quad& b) {
  return a.corner == b.corner && a.edge_u == b.edge_u && a.edge_v == b.edge_v;
}

}  // namespace

std::vector<std::string> path_scene_names() {
  return {"cornell", "cornell-spheres", "furnace", "whitted", "spheres", "s10", "aliasing", "soft"};
}

Scene make_path_scene_by_name(const std::string& name) {
  if (name == "cornell") return cornell_box_scene(cornell_box_data(CornellContents::Blocks));
  if (name == "cornell-spheres") return cornell_box_scene(cornell_box_data(CornellContents::Spheres));
  if (name == "furnace") return furnace_scene(0.5, 1.0);
  for (const std::string& whitted : scene_names())
    if (name == whitted) return physical_scene(make_scene(name));
  std::string known;
  for (const std::string& n : path_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + name + "' (path-traced scenes: " + known + ")");
}

Scene furnace_scene(double rho, double emitted_radiance) {
  if (!(rho >= 0 && rho < 1)) throw std::invalid_argument("furnace: rho must lie in [0, 1)");
  if (!(emitted_radiance > 0 && std::isfinite(emitted_radiance)))
    throw std::invalid_argument("furnace: the emitted radiance must be positive and finite");
  Scene s;
  s.name = "furnace";
  Material wall;
  wall.name = "wall";
  wall.diffuse = Color(rho);
  wall.emission = Color(emitted_radiance);
  const int material = s.add(wall);
  for (Quad q : box_quads(vec3(0.0), vec3(1.0), material)) {
    std::swap(q.edge_u, q.edge_v);  // the same face, turned to face the inside
    s.add(q);
  }
  s.camera = Camera{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.0}, {0, 1, 0}, 90};
  return s;
}

Scene physical_scene(const Scene& whitted) {
  Scene s = whitted;
  s.lights.clear();
  s.area_lights.clear();
  s.ambient_light = Color(0.0);
  const vec3 target = whitted.camera.look_at;
  for (std::size_t i = 0; i < whitted.lights.size(); ++i) {
    const PointLight& light = whitted.lights[i];
    const double d = std::max(1e-6, length(light.position - target)), r = 0.02 * d;
    const int m = s.add(emitter("light " + std::to_string(i), light.intensity * (d * d / (r * r))));
    s.add(Sphere{light.position, r, m});
  }
  for (std::size_t i = 0; i < whitted.area_lights.size(); ++i) {
    const QuadLight& light = whitted.area_lights[i];
    const double d = std::max(1e-6, length(centre(light.shape) - target));
    const Color radiance = light.intensity * (pi * d * d / area(light.shape));
    const int m = s.add(emitter("area light " + std::to_string(i), radiance));
    bool reused = false;
    for (Quad& q : s.quads)
      if (same_shape(q, light.shape) && max_component(s.materials[q.material].emission) > 0)
        q.material = m, reused = true;
    if (!reused) s.add(Quad{light.shape.corner, light.shape.edge_u, light.shape.edge_v, m});
  }
  return s;
}

}  // namespace gi
