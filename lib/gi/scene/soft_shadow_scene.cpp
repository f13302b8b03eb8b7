#include "gi/scene/soft_shadow_scene.hpp"

#include <stdexcept>

namespace gi {

namespace {

Material matte(const std::string& name, Color colour, double specular) {
  Material m;
  m.name = name;
  m.diffuse = colour;
  m.ambient = 0.1;
  m.specular = Color(specular);
  m.shininess = 30;
  return m;
}

}  // namespace

Scene soft_shadow_scene(double light_size) {
  if (!(light_size >= 0 && light_size <= 10))
    throw std::invalid_argument("soft shadows: the light size must lie in [0, 10]");
  Scene s;
  s.name = "soft";
  s.background = Color(0.02);
  s.ambient_light = Color(0.3);
  const int floor = s.add(matte("floor", Color(0.75), 0.0));
  const int box = s.add(matte("box", Color(0.9, 0.45, 0.15), 0.3));
  const int ball = s.add(matte("ball", Color(0.2, 0.35, 0.85), 0.5));
  const int pole = s.add(matte("pole", Color(0.85), 0.2));
  s.add(Plane{{0, 0, 0}, {0, 1, 0}, floor});
  const double h = soft_shadow_box_height, edge = soft_shadow_box_edge_x;
  for (const Quad& q : box_quads({edge - 1.0, 0, -0.6}, {edge, h, 0.6}, box)) s.add(q);
  s.add(Sphere{{-1.4, 0.6, 0.4}, 0.6, ball});
  for (const Quad& q : box_quads({-0.3, 0, -1.6}, {-0.24, 2.4, -1.54}, pole)) s.add(q);

  const vec3 centre(soft_shadow_light_x, soft_shadow_light_height, soft_shadow_light_z);
  if (light_size == 0) {
    s.add(PointLight{centre, Color(1.0)});
  } else {
    // Edges along z then x: the normal points down, at the floor.
    const Quad shape{centre - 0.5 * light_size * vec3(1, 0, 1), {0, 0, light_size}, {light_size, 0, 0}, 0};
    s.add(QuadLight{shape, Color(1.0)});
    Material glow;
    glow.name = "light";
    glow.diffuse = Color(0.0);
    glow.emission = Color(1.0);
    const int light = s.add(glow);
    s.add(Quad{shape.corner, shape.edge_u, shape.edge_v, light});  // what the camera sees of it
  }
  s.camera = Camera{{0.6, 3.6, 6.5}, {0.3, 0.3, 0}, {0, 1, 0}, 45};
  return s;
}

}  // namespace gi
