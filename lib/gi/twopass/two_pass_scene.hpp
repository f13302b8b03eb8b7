#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/material.hpp"
#include "gi/geometry/sphere.hpp"

namespace gi {

// What the two-pass renderer draws: the diffuse surfaces radiosity can mesh (the
// lights among them, E > 0) and the specular spheres it cannot (a mirror, glass),
// seen through one camera. The two halves of the course meet here: the surfaces are
// radiosity's Surfaces, the spheres the ray tracer's Spheres with their Materials.
struct SpecularSphere {
  Sphere shape;       // shape.material is unused: the material is below
  Material material;  // mirror (k_r) or dielectric (transmission, ior); diffuse is ignored
};

struct TwoPassScene {
  std::string name;
  std::vector<Surface> surfaces;
  std::vector<SpecularSphere> spheres;
  Camera camera;
};

// The scenes by name, the path tracer's scenes of the same names (path_scenes.hpp):
//   cornell          the diffuse Cornell box with its two blocks
//   cornell-spheres  the box with a mirror sphere and a glass sphere instead of the blocks
std::vector<std::string> two_pass_scene_names();
TwoPassScene make_two_pass_scene(const std::string& name);  // throws std::invalid_argument, listing the names

}  // namespace gi
