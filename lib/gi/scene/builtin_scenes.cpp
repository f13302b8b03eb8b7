#include "gi/scene/builtin_scenes.hpp"

#include <stdexcept>

#include "gi/scene/soft_shadow_scene.hpp"

namespace gi {

namespace {

// k_d as written: the scenes' files (lessons/scenes/) carry the same numbers.
Material phong_plastic(const std::string& name, Color kd, double shininess) {
  Material m;
  m.name = name;
  m.diffuse = kd;
  m.ambient = 0.1;
  m.specular = Color(0.5);
  m.shininess = shininess;
  return m;
}

Material glass(Color filter) {
  Material m;
  m.name = "glass";
  m.diffuse = Color(0.0);
  m.specular = Color(0.9);
  m.shininess = 120;
  m.transmission = filter;
  m.ior = 1.5;
  return m;
}

Material mirror(Color reflectance) {
  Material m;
  m.name = "mirror";
  m.diffuse = Color(0.05);
  m.specular = Color(0.8);
  m.shininess = 80;
  m.mirror = reflectance;
  return m;
}

Scene whitted() {
  Scene s;
  s.name = "whitted";
  s.background = Color(0.35, 0.55, 0.9);
  s.ambient_light = Color(1.0);
  Material floor = phong_plastic("checkerboard", Color(0.8, 0.08, 0.04), 1);
  floor.specular = Color(0.0);
  floor.checker_size = 1.0;
  floor.checker_diffuse = Color(0.8, 0.72, 0.08);
  const int checker = s.add(floor);
  const int mirror_ball = s.add(mirror(Color(0.8)));
  const int glass_ball = s.add(glass(Color(0.95)));
  // A finite board, as in Whitted's picture, so the sky shows past its far edge.
  s.add(Quad{{-4, 0, 4}, {8, 0, 0}, {0, 0, -18}, checker});
  s.add(Sphere{{-1.3, 1.3, -3.4}, 1.1, mirror_ball});
  s.add(Sphere{{0.9, 1.1, -0.5}, 0.9, glass_ball});
  s.add(PointLight{{-4, 8, 6}, Color(0.9)});
  s.camera = Camera{{0.0, 1.8, 5.5}, {-0.2, 1.0, -1.5}, {0, 1, 0}, 40};
  return s;
}

Scene spheres() {
  Scene s;
  s.name = "spheres";
  s.background = Color(0.05, 0.05, 0.08);
  s.ambient_light = Color(1.0);
  Material grey = phong_plastic("grey floor", Color(0.56), 1);
  grey.specular = Color(0.0);
  const int floor = s.add(grey);
  const int red = s.add(phong_plastic("red", Color(0.72, 0.12, 0.08), 30));
  const int green = s.add(phong_plastic("green", Color(0.12, 0.64, 0.16), 30));
  const int blue = s.add(phong_plastic("blue", Color(0.12, 0.24, 0.72), 30));
  s.add(Plane{{0, 0, 0}, {0, 1, 0}, floor});
  s.add(Sphere{{-1.6, 0.8, -4.0}, 0.8, red});
  s.add(Sphere{{0.0, 1.0, -5.5}, 1.0, green});
  s.add(Sphere{{1.5, 0.6, -3.5}, 0.6, blue});
  s.add(PointLight{{-3, 6, 1}, Color(0.9)});
  s.camera = Camera{{0, 1.5, 2}, {0, 0.8, -4}, {0, 1, 0}, 45};
  return s;
}

// lessons/scenes/s10.tachyon.dat, translated, so the two renderers can be timed on
// the same picture. Tachyon's view is left-handed (looking down +z, +x is on the
// left), ours right-handed, so every x is negated to keep the picture the same way
// round. Tachyon's k_d is DIFFUSE 0.8 times COLOR. Its glass only lets light through
// (opacity); ours refracts it.
Scene s10() {
  Scene s;
  s.name = "s10";
  s.background = Color(0.25, 0.35, 0.55);
  s.ambient_light = Color(1.0);
  Material floor = phong_plastic("floor", Color(0.72, 0.16, 0.04), 10);
  floor.specular = Color(0.0);
  floor.checker_size = 0.5;
  floor.checker_diffuse = Color(0.04, 0.08, 0.72);
  const int floor_id = s.add(floor);
  s.add(Plane{{0, 0, 0}, {0, 1, 0}, floor_id});
  const Color kd[8] = {{0.72, 0.16, 0.16}, {0.16, 0.64, 0.16}, {0.16, 0.24, 0.72}, {0.72, 0.64, 0.16},
                       {0.64, 0.24, 0.64}, {0.16, 0.64, 0.64}, {0.76, 0.44, 0.12}, {0.48, 0.48, 0.48}};
  const vec3 centres[8] = {{4.6985, 0.8, 5.0261},  {3.8302, 0.8, 5.9284},  {2.5, 0.8, 6.5981},
                           {0.8682, 0.8, 6.9544},  {-0.8682, 0.8, 6.9544}, {-2.5, 0.8, 6.5981},
                           {-3.8302, 0.8, 5.9284}, {-4.6985, 0.8, 5.0261}};
  for (int i = 0; i < 8; ++i)
    s.add(Sphere{centres[i], 0.8, s.add(phong_plastic("ball " + std::to_string(i), kd[i], 40))});
  s.add(Sphere{{1.3, 1.3, 2.2}, 1.3, s.add(mirror(Color(0.9)))});
  s.add(Sphere{{-1.4, 1.1, 0.8}, 1.1, s.add(glass(Color(0.9, 0.95, 1.0)))});
  s.add(PointLight{{10, 9, 3}, Color(0.6)});
  s.add(PointLight{{-9, 6, 0}, Color(0.4)});
  s.camera = Camera{{0, 3.5, -6}, {0, 3.2, -5}, {0, 1, 0}, 54};  // Tachyon's VIEWDIR 0 -0.3 1
  return s;
}

// Everything that aliases: a black-and-white checkerboard receding to the horizon
// (moire), thin poles and a wire narrower than a pixel, and sharp shadow edges.
Scene aliasing() {
  Scene s;
  s.name = "aliasing";
  s.background = Color(0.55, 0.7, 0.9);
  s.ambient_light = Color(1.0);
  Material board = phong_plastic("checkerboard", Color(0.8), 1);
  board.specular = Color(0.0);
  board.checker_size = 1.0;
  board.checker_diffuse = Color(0.02);
  const int floor = s.add(board);
  Material pole = phong_plastic("pole", Color(0.72, 0.2, 0.08), 20);
  const int poles = s.add(pole);
  s.add(Plane{{0, 0, 0}, {0, 1, 0}, floor});
  const double pole_x[6] = {-1.2, 1.3, -1.0, 1.5, -0.8, 1.7};
  for (int i = 0; i < 6; ++i)  // poles 3 cm wide, ever farther away
    s.add(Quad{{pole_x[i], 0, -3.0 - 2.5 * i}, {0.03, 0, 0}, {0, 2.2, 0}, poles});
  s.add(Quad{{-6, 1.9, -9}, {12, 0, 0}, {0, 0.01, 0}, poles});  // a wire, 1 cm thick
  s.add(Sphere{{0.4, 0.6, -5}, 0.6, s.add(phong_plastic("ball", Color(0.16, 0.32, 0.72), 40))});
  s.add(PointLight{{-4, 6, 2}, Color(0.8)});
  s.camera = Camera{{0, 1.2, 1.5}, {0, 0.7, -8}, {0, 1, 0}, 50};
  return s;
}

}  // namespace

std::vector<std::string> scene_names() { return {"whitted", "spheres", "s10", "aliasing", "soft"}; }

Scene make_scene(const std::string& name) {
  if (name == "whitted") return whitted();
  if (name == "spheres") return spheres();
  if (name == "s10") return s10();
  if (name == "aliasing") return aliasing();
  if (name == "soft") return soft_shadow_scene(1.0);
  std::string known;
  for (const std::string& n : scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + name + "' (built-in scenes: " + known + ")");
}

}  // namespace gi
