#include "gi/twopass/eye_world.hpp"

namespace gi {

EyeWorld make_eye_world(const Mesh& mesh, const std::vector<SpecularSphere>& spheres) {
  Scene scene;
  scene.name = "two-pass eye world";
  for (const Surface& s : mesh.surfaces) {
    Material m;
    m.name = s.name;
    m.diffuse = s.reflectance;
    m.emission = s.emission / pi;  // radiance L = E / pi of a Lambertian emitter
    scene.add(m);
  }
  // Element e is triangles 2e and 2e + 1.
  for (const Element& e : mesh.elements) {
    const auto& c = e.shape.corners;
    scene.add(Triangle{c[0], c[1], c[2], e.surface});
    scene.add(Triangle{c[0], c[2], c[3], e.surface});
  }
  for (const SpecularSphere& s : spheres) {
    Sphere shape = s.shape;
    shape.material = scene.add(s.material);
    scene.add(shape);
  }
  return {make_world(std::move(scene)), static_cast<int>(mesh.surfaces.size())};
}

std::optional<EyeHit> first_hit(const EyeWorld& eye, const Ray& ray) {
  const auto hit = closest_hit(eye.world, ray);
  if (!hit) return std::nullopt;
  // Triangles carry their surface's material, spheres theirs after the surfaces'.
  return EyeHit{*hit, hit->material < eye.surface_count ? hit->object / 2 : -1};
}

bool unoccluded(const EyeWorld& eye, const vec3& x, const vec3& y) {
  const vec3 d = y - x;
  const double distance = length(d);
  // Shorter at both ends by a relative hair: x's own surface and the light's are not blockers.
  const double eps = 1e-7 * distance;
  return !any_hit(eye.world, Ray{x, d / distance, eps, distance - eps});
}

}  // namespace gi
