#pragma once
#include <string>
#include <vector>

#include "gi/geometry/plane.hpp"
#include "gi/geometry/quad.hpp"
#include "gi/geometry/sphere.hpp"
#include "gi/geometry/triangle.hpp"
#include "gi/scene/camera.hpp"
#include "gi/scene/light.hpp"
#include "gi/scene/material.hpp"

namespace gi {

// A scene is plain data: one vector per kind of primitive, the materials they
// index, the lights and a camera. Model no more than a scene needs.
struct Scene {
  std::string name;
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<Plane> planes;
  std::vector<Quad> quads;
  std::vector<Triangle> triangles;  // meshes: the radiosity lessons cast rays into their elements
  std::vector<PointLight> lights;
  std::vector<QuadLight> area_lights;  // lesson 04; add an emitting quad too if the camera should see it
  Color background{0.0};     // radiance of rays that hit nothing
  Color ambient_light{0.0};  // I_a of the Phong model
  Camera camera;

  // Adders check their argument (and that its material exists) and throw
  // std::invalid_argument with a clear message otherwise.
  int add(const Material& material);  // returns the material's index
  void add(const Sphere& sphere);
  void add(const Plane& plane);
  void add(const Quad& quad);
  void add(const Triangle& triangle);
  void add(const PointLight& light);
  void add(const QuadLight& light);

  std::size_t primitive_count() const { return spheres.size() + planes.size() + quads.size() + triangles.size(); }
};

// Throws std::invalid_argument if anything in the scene is invalid (for scenes
// assembled by hand rather than through the adders).
void check(const Scene& scene);

// A digest of every value in the scene (FNV-1a, 16 hex digits): scenes with the same
// fingerprint render the same. It names the scene in a cached reference's key, so an
// edited scene file is rendered again.
std::string fingerprint(const Scene& scene);

}  // namespace gi
