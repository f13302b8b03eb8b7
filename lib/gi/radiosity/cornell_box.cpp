#include "gi/radiosity/radiosity_scenes.hpp"

namespace gi {

RadiosityScene cornell_box(bool closed) {
  const Color white(0.725, 0.71, 0.68), red(0.63, 0.065, 0.05), green(0.14, 0.45, 0.091);
  const Color light_exitance = pi * Color(17, 12, 4);
  RadiosityScene s;
  s.name = "cornell";
  auto add = [&](const std::string& name, std::array<vec3, 4> corners, Color rho, Color e = Color(0.0)) {
    s.surfaces.push_back({name, corners, rho, e});
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
  add("light", {{{343, y, 227}, {343, y, 332}, {213, y, 332}, {213, y, 227}}}, Color(0.78), light_exitance);
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
  if (closed) add("front (black)", {{{552.8, 0, 0}, {556, 548.8, 0}, {0, 548.8, 0}, {0, 0, 0}}}, Color(0.0));
  // Focal length 35 mm, film 25 mm: vertical field of view 2 atan(12.5 / 35).
  s.camera = Camera{{278, 273, -800}, {278, 273, 0}, {0, 1, 0}, 2 * std::atan(12.5 / 35) * 180 / pi};
  return s;
}

}  // namespace gi
