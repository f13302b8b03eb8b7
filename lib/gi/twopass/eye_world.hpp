#pragma once
#include <optional>

#include "gi/accel/world.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/twopass/two_pass_scene.hpp"

namespace gi {

// What the eye pass casts its rays into: the radiosity mesh's elements (two triangles
// each, the split form factors use) and the specular spheres, in one World. A hit on a
// diffuse surface names its element, so the eye pass can read the radiosity solution
// exactly where the ray landed; the spheres shadow and reflect like any other object.
// Materials 0 .. surfaces - 1 are the mesh's surfaces (diffuse = rho, emission = E / pi),
// the spheres' follow.
struct EyeWorld {
  World world;
  int surface_count = 0;
};

EyeWorld make_eye_world(const Mesh& mesh, const std::vector<SpecularSphere>& spheres);

// A ray's first hit, with the element it landed on (-1 for a sphere).
struct EyeHit {
  Hit hit;
  int element = -1;
};
std::optional<EyeHit> first_hit(const EyeWorld& eye, const Ray& ray);

// Is the segment from x to y clear? (The ends excluded: x is on a surface, y on a light.)
bool unoccluded(const EyeWorld& eye, const vec3& x, const vec3& y);

}  // namespace gi
