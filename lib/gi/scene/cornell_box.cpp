#include "gi/scene/cornell_box.hpp"

#include <cmath>

#include "gi/scene/cornell_spectra.hpp"

namespace gi {

CornellPalette cornell_palette(const CornellPaletteChoice& choice) {
  CornellPalette p;
  if (choice.reflectances == CornellReflectances::Published) {
    p.white = rgb_band_means(cornell_white_spectrum());
    p.red = rgb_band_means(cornell_red_spectrum());
    p.green = rgb_band_means(cornell_green_spectrum());
  } else {
    p.white = Color(0.725, 0.71, 0.68);
    p.red = Color(0.63, 0.065, 0.05);
    p.green = Color(0.14, 0.45, 0.091);
  }
  // A Lambertian emitter of radiance L has exitance E = pi L.
  p.light_exitance = choice.light == CornellLight::Published ? pi * rgb_band_means(cornell_light_spectrum()) : Color(1.0);
  p.light_reflectance = Color(choice.light_reflects ? 0.78 : 0.0);
  p.mirror = Color(0.95);
  p.glass_ior = 1.5;
  return p;
}

CornellBox cornell_box_data(CornellContents contents, bool closed, const CornellPalette& p) {
  const Color &white = p.white, &red = p.red, &green = p.green;
  CornellBox box;
  auto add = [&](const std::string& name, std::array<vec3, 4> corners, Color rho, Color e = Color(0.0)) {
    box.surfaces.push_back({name, corners, rho, e});
  };
  add("floor", {{{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}}}, white);
  add("back wall", {{{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}}, white);
  add("red wall", {{{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}}}, red);
  add("green wall", {{{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}}}, green);
  // The ceiling (556 x 559.2 at y = 548.8) around the light's hole x 213..343, z 227..332.
  const double y = 548.8;
  add("ceiling front", {{{556, y, 0}, {556, y, 227}, {0, y, 227}, {0, y, 0}}}, white);
  add("ceiling back", {{{556, y, 332}, {556, y, 559.2}, {0, y, 559.2}, {0, y, 332}}}, white);
  add("ceiling red side", {{{556, y, 227}, {556, y, 332}, {343, y, 332}, {343, y, 227}}}, white);
  add("ceiling green side", {{{213, y, 227}, {213, y, 332}, {0, y, 332}, {0, y, 227}}}, white);
  add("light", {{{343, y, 227}, {343, y, 332}, {213, y, 332}, {213, y, 227}}}, p.light_reflectance, p.light_exitance);
  if (contents == CornellContents::Blocks) {
    add("short block top", {{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}, white);
    add("short block 1", {{{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}}, white);
    add("short block 2", {{{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}}, white);
    add("short block 3", {{{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}}, white);
    add("short block 4", {{{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}}, white);
    add("tall block top", {{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}, white);
    add("tall block 1", {{{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}}, white);
    add("tall block 2", {{{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}}, white);
    add("tall block 3", {{{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}}, white);
    add("tall block 4", {{{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}}, white);
  } else {
    // Resting on the floor, clear of each other and of the walls; the glass sphere is
    // in front of the light, so its caustic falls on the floor in view.
    box.spheres = {{"mirror sphere", {370, 90, 370}, 90, false}, {"glass sphere", {180, 90, 170}, 90, true}};
  }
  if (closed) add("front (black)", {{{552.8, 0, 0}, {556, 548.8, 0}, {0, 548.8, 0}, {0, 0, 0}}}, Color(0.0));
  // Focal length 35 mm, film 25 mm: vertical field of view 2 atan(12.5 / 35).
  box.camera = Camera{{278, 273, -800}, {278, 273, 0}, {0, 1, 0}, 2 * std::atan(12.5 / 35) * 180 / pi};
  return box;
}

Scene cornell_box_scene(const CornellBox& box, const CornellPalette& p) {
  Scene s;
  s.name = box.spheres.empty() ? "cornell" : "cornell-spheres";
  for (const QuadSurface& q : box.surfaces) {
    Material m;
    m.name = q.name;
    m.diffuse = q.reflectance;
    m.emission = q.exitance / pi;  // a Lambertian emitter: L = E / pi
    const int material = s.add(m);
    const auto& c = q.corners;
    s.add(Triangle{c[0], c[1], c[2], material});
    s.add(Triangle{c[0], c[2], c[3], material});
  }
  for (const CornellSphere& sphere : box.spheres) {
    Material m;
    m.name = sphere.name;
    m.diffuse = Color(0.0);
    if (sphere.glass) {
      m.transmission = Color(1.0);
      m.ior = p.glass_ior;
    } else {
      m.mirror = p.mirror;
    }
    s.add(Sphere{sphere.centre, sphere.radius, s.add(m)});
  }
  s.camera = box.camera;
  return s;
}

}  // namespace gi
