#include <stdexcept>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace gi {

namespace {

// The square (or rectangle) centred at `centre` spanned by u and v, facing u x v.
Surface square(const std::string& name, vec3 centre, vec3 u, vec3 v, Color rho, Color e = Color(0.0)) {
  const vec3 c0 = centre - 0.5 * u - 0.5 * v;
  return {name, {c0, c0 + u, c0 + u + v, c0 + v}, rho, e};
}

void require_positive(double a, double b) {
  if (!(a > 0 && b > 0 && a < 1e6 && b < 1e6)) throw std::invalid_argument("scene: sizes must lie in (0, 1e6)");
}

const Color grey(0.5), emitter(1.0), black(0.0);

// Camera outside the unit-ish scene, looking at its middle.
Camera camera_for(double size) { return Camera{{1.2 * size, 1.6 * size, 3.2 * size}, {0.5 * size, 0.4 * size, 0.5 * size}, {0, 1, 0}, 40}; }

// The six inward faces of the cube [0, a]^3; the ceiling is the light.
std::vector<Surface> box_faces(double a) {
  const double h = 0.5 * a;
  return {square("floor", {h, 0, h}, {0, 0, a}, {a, 0, 0}, grey),
          square("ceiling", {h, a, h}, {a, 0, 0}, {0, 0, a}, grey, emitter),
          square("wall x=0", {0, h, h}, {0, a, 0}, {0, 0, a}, grey),
          square("wall x=a", {a, h, h}, {0, 0, a}, {0, a, 0}, grey),
          square("wall z=0", {h, h, 0}, {a, 0, 0}, {0, a, 0}, grey),
          square("wall z=a", {h, h, a}, {0, a, 0}, {a, 0, 0}, grey)};
}

}  // namespace

RadiosityScene parallel_squares(double side, double distance) {
  require_positive(side, distance);
  const double a = side;
  return {"parallel",
          {square("bottom", {0, 0, 0}, {0, 0, a}, {a, 0, 0}, black, emitter),
           square("top", {0, distance, 0}, {a, 0, 0}, {0, 0, a}, grey)},
          Camera{{2 * a, 1.5 * distance, 3 * a}, {0, 0.5 * distance, 0}, {0, 1, 0}, 40}};
}

RadiosityScene perpendicular_squares(double side) {
  require_positive(side, side);
  const double a = side, h = 0.5 * side;
  return {"perpendicular",
          {square("floor", {h, 0, h}, {0, 0, a}, {a, 0, 0}, grey),
           square("wall", {h, h, 0}, {a, 0, 0}, {0, a, 0}, black, emitter)},
          camera_for(a)};
}

RadiosityScene closed_box(double side) {
  require_positive(side, side);
  return {"closed-box", box_faces(side), camera_for(side)};
}

RadiosityScene open_box(double side) {
  require_positive(side, side);
  std::vector<Surface> faces = box_faces(side);
  faces.erase(faces.begin() + 1);  // no ceiling: the floor is the light
  faces[0].emission = emitter;
  return {"open-box", faces, camera_for(side)};
}

RadiosityScene occluded_squares(double side, double distance) {
  require_positive(side, distance);
  const double a = side, b = 0.5 * side, m = 0.5 * distance, gap = 0.005 * side;
  // The blocker is two half-size squares back to back, 1% of a side apart (a thin
  // slab): opaque from both sides, with no tie between its faces for a z-buffer.
  return {"occluded",
          {square("bottom", {0, 0, 0}, {0, 0, a}, {a, 0, 0}, black, emitter),
           square("top", {0, distance, 0}, {a, 0, 0}, {0, 0, a}, grey),
           square("blocker underside", {0, m - gap, 0}, {b, 0, 0}, {0, 0, b}, grey),
           square("blocker top", {0, m + gap, 0}, {0, 0, b}, {b, 0, 0}, grey)},
          Camera{{2 * a, 1.5 * distance, 3 * a}, {0, 0.5 * distance, 0}, {0, 1, 0}, 40}};
}

std::vector<std::string> radiosity_scene_names() {
  return {"cornell", "parallel", "perpendicular", "closed-box", "open-box", "occluded"};
}

RadiosityScene make_radiosity_scene(const std::string& name) {
  if (name == "cornell") return cornell_box();
  if (name == "parallel") return parallel_squares();
  if (name == "perpendicular") return perpendicular_squares();
  if (name == "closed-box") return closed_box();
  if (name == "open-box") return open_box();
  if (name == "occluded") return occluded_squares();
  std::string known;
  for (const std::string& n : radiosity_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown radiosity scene '" + name + "' (" + known + ")");
}

}  // namespace gi
