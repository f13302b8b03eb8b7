#include "gi/scene/benchmark_scenes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gi/core/rng.hpp"

namespace gi {

namespace {

Material matte(const std::string& name, Color colour) {
  Material m;
  m.name = name;
  m.diffuse = 0.8 * colour;
  m.ambient = 0.1;
  return m;
}

// The faces of the box [lo, hi] (box_quads), turned to face `inwards` for the inside
// of a room. `bottom` = false leaves out the face at low y, where a box stands on
// something: a hidden face in the floor's plane that would tie with it for hits.
std::vector<Quad> box_faces(const vec3& lo, const vec3& hi, int material, bool inwards, bool bottom) {
  std::vector<Quad> faces;
  for (Quad q : box_quads(lo, hi, material)) {
    if (!bottom && normal(q).y < -0.5) continue;
    if (inwards) std::swap(q.edge_u, q.edge_v);  // the same parallelogram, facing the other way
    faces.push_back(q);
  }
  return faces;
}

// Into how many parts an edge of this length is cut, for quads of side about `side`.
int parts(const vec3& edge, double side) { return std::max(1, static_cast<int>(std::lround(length(edge) / side))); }

std::size_t quad_count(const std::vector<Quad>& faces, double side) {
  std::size_t count = 0;
  for (const Quad& f : faces) count += static_cast<std::size_t>(parts(f.edge_u, side)) * parts(f.edge_v, side);
  return count;
}

}  // namespace

Scene random_spheres(int count, std::uint64_t seed) {
  if (count < 1) throw std::invalid_argument("random_spheres: count must be at least 1, got " + std::to_string(count));
  Scene s;
  s.name = "random spheres (" + std::to_string(count) + ")";
  s.background = Color(0.2, 0.25, 0.35);
  s.ambient_light = Color(1.0);
  const Color colours[4] = {{0.9, 0.3, 0.2}, {0.3, 0.8, 0.3}, {0.3, 0.4, 0.9}, {0.9, 0.8, 0.3}};
  for (int i = 0; i < 4; ++i) s.add(matte("sphere " + std::to_string(i), colours[i]));
  // count * (4/3) pi r^3 = 0.05 * 10^3
  const double fill = 0.05, side = 10.0;
  const double radius = side * std::cbrt(3.0 * fill / (4.0 * pi * count));
  Rng rng(seed);
  for (int i = 0; i < count; ++i) {
    // Drawn one at a time, z first: the arguments of one call would come in an order
    // of the compiler's choosing (GCC's was z, y, x; Clang's x, y, z), and the scene
    // would depend on the compiler.
    const double z = rng.uniform(), y = rng.uniform(), x = rng.uniform();
    const vec3 centre = side * vec3(x, y, z) - 0.5 * side;
    s.add(Sphere{centre, radius, static_cast<int>(rng.below(4))});
  }
  s.add(PointLight{{10, 15, 15}, Color(0.9)});
  s.camera = Camera{{6, 4, 17}, {0, 0, 0}, {0, 1, 0}, 40};
  return s;
}

Aabb quad_room_interior() { return Aabb{{-4.9, 0.1, -4.9}, {4.9, 3.4, 4.9}}; }

Scene quad_room(int target_quads) {
  if (target_quads < 1)
    throw std::invalid_argument("quad_room: target_quads must be at least 1, got " + std::to_string(target_quads));
  Scene s;
  s.name = "quad room (" + std::to_string(target_quads) + ")";
  s.ambient_light = Color(1.0);
  const int white = s.add(matte("white wall", Color(0.9)));
  const int red = s.add(matte("red wall", Color(0.9, 0.2, 0.15)));
  const int green = s.add(matte("green wall", Color(0.2, 0.8, 0.25)));
  const int floor = s.add(matte("floor", Color(0.6, 0.5, 0.4)));
  const int wood = s.add(matte("wood", Color(0.55, 0.35, 0.2)));
  const int blue = s.add(matte("sofa", Color(0.2, 0.3, 0.8)));

  // The room is [-5, 5] x [0, 3.5] x [-5, 5]. Furniture keeps clear of the walls. Where
  // two pieces meet, one stands on the other (and has no bottom face) or reaches into
  // it, so that no two faces overlap in one plane.
  std::vector<Quad> faces;
  const auto add = [&faces](const std::vector<Quad>& more) { faces.insert(faces.end(), more.begin(), more.end()); };
  for (Quad wall : box_faces({-5, 0, -5}, {5, 3.5, 5}, white, true, true)) {
    const vec3 n = normal(wall);
    wall.material = n.y > 0.5 ? floor : n.x > 0.5 ? red : n.x < -0.5 ? green : white;
    faces.push_back(wall);
  }
  add(box_faces({-1.2, 0.72, -1.6}, {1.2, 0.78, -0.4}, wood, false, true));  // table top
  for (const double x : {-1.1, 1.02})
    for (const double z : {-1.5, -0.58}) add(box_faces({x, 0, z}, {x + 0.08, 0.75, z + 0.08}, wood, false, false));
  add(box_faces({2.8, 0, -4.9}, {4.6, 2.2, -4.3}, wood, false, false));    // cabinet
  add(box_faces({-4.8, 0, 0.5}, {-3.8, 0.45, 3.0}, blue, false, false));   // sofa seat
  add(box_faces({-4.95, 0, 0.45}, {-4.7, 0.9, 3.05}, blue, false, false));  // its back
  add(box_faces({3.0, 0, 1.5}, {4.0, 1.0, 2.5}, wood, false, false));      // crates, stacked
  add(box_faces({3.2, 1.0, 1.7}, {3.9, 1.7, 2.4}, red, false, false));
  add(box_faces({3.35, 1.7, 1.85}, {3.8, 2.15, 2.3}, green, false, false));

  // One quad size for all faces: the largest whose grids give at least the target,
  // found by bisection (the count falls as the size grows).
  double fine = 1e-4, coarse = 10.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(fine * coarse);
    (quad_count(faces, mid) >= static_cast<std::size_t>(target_quads) ? fine : coarse) = mid;
  }
  for (const Quad& f : faces) {
    const int nu = parts(f.edge_u, fine), nv = parts(f.edge_v, fine);
    const vec3 du = f.edge_u / static_cast<double>(nu), dv = f.edge_v / static_cast<double>(nv);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) s.add(Quad{f.corner + double(i) * du + double(j) * dv, du, dv, f.material});
  }
  s.add(PointLight{{0, 3.2, 0}, Color(0.7)});
  s.add(PointLight{{-3, 2.5, 3.5}, Color(0.3)});
  s.camera = Camera{{0.5, 1.6, 4.6}, {-0.3, 0.9, -2}, {0, 1, 0}, 65};
  return s;
}

}  // namespace gi
