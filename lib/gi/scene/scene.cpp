#include "gi/scene/scene.hpp"

#include <cstring>
#include <stdexcept>

#include "gi/core/hash.hpp"

namespace gi {

namespace {

void check_material_index(const Scene& scene, int material) {
  if (material < 0 || material >= static_cast<int>(scene.materials.size()))
    throw std::invalid_argument("scene '" + scene.name + "': material index " + std::to_string(material) +
                                " does not exist (add the material first)");
}

void check(const Material& m) {
  const bool finite = is_finite(m.diffuse) && is_finite(m.specular) && is_finite(m.mirror) &&
                      is_finite(m.transmission) && is_finite(m.emission) && std::isfinite(m.ambient) &&
                      std::isfinite(m.shininess) && std::isfinite(m.ior) && std::isfinite(m.checker_size);
  if (!finite) throw std::invalid_argument("material '" + m.name + "': every value must be finite");
  if (m.shininess < 0) throw std::invalid_argument("material '" + m.name + "': shininess must be >= 0");
  if (m.is_dielectric() && m.ior <= 0)
    throw std::invalid_argument("material '" + m.name + "': a transparent material needs an index of refraction > 0");
}

}  // namespace

int Scene::add(const Material& material) {
  check(material);
  materials.push_back(material);
  return static_cast<int>(materials.size()) - 1;
}

void Scene::add(const Sphere& sphere) {
  check(sphere);
  check_material_index(*this, sphere.material);
  spheres.push_back(sphere);
}

void Scene::add(const Plane& plane) {
  check(plane);
  check_material_index(*this, plane.material);
  planes.push_back(plane);
}

void Scene::add(const Quad& quad) {
  check(quad);
  check_material_index(*this, quad.material);
  quads.push_back(quad);
}

void Scene::add(const Triangle& triangle) {
  check(triangle);
  check_material_index(*this, triangle.material);
  triangles.push_back(triangle);
}

void Scene::add(const PointLight& light) {
  if (!is_finite(light.position) || !is_finite(light.intensity))
    throw std::invalid_argument("point light: position and intensity must be finite");
  lights.push_back(light);
}

void Scene::add(const QuadLight& light) {
  check(light.shape);
  if (!is_finite(light.intensity)) throw std::invalid_argument("area light: intensity must be finite");
  area_lights.push_back(light);
}

void check(const Scene& scene) {
  for (const Material& m : scene.materials) check(m);
  for (const Sphere& s : scene.spheres) check(s), check_material_index(scene, s.material);
  for (const Plane& p : scene.planes) check(p), check_material_index(scene, p.material);
  for (const Quad& q : scene.quads) check(q), check_material_index(scene, q.material);
  for (const Triangle& t : scene.triangles) check(t), check_material_index(scene, t.material);
  for (const QuadLight& l : scene.area_lights) check(l.shape);
  (void)camera_frame(scene.camera, 1, 1);  // throws for a degenerate camera
}

namespace {

// Feeds values to FNV-1a by their bytes (doubles exactly, not as printed).
struct Digest {
  std::uint64_t h = fnv1a("");
  Digest& operator<<(double v) {
    char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    h = fnv1a(std::string_view(bytes, sizeof v), h);
    return *this;
  }
  Digest& operator<<(const vec3& v) { return *this << v.x << v.y << v.z; }
  Digest& operator<<(std::size_t n) { return *this << static_cast<double>(n); }
  Digest& operator<<(int n) { return *this << static_cast<double>(n); }
  Digest& operator<<(const std::string& text) {
    *this << text.size();
    h = fnv1a(text, h);
    return *this;
  }
};

}  // namespace

std::string fingerprint(const Scene& scene) {
  Digest d;
  d << scene.name << scene.background << scene.ambient_light << scene.camera.eye << scene.camera.look_at
    << scene.camera.up << scene.camera.vertical_fov;
  for (const Material& m : scene.materials)
    d << m.name << m.diffuse << m.ambient << m.specular << m.shininess << m.mirror << m.transmission << m.ior
      << m.emission << m.checker_size << m.checker_diffuse;
  d << scene.spheres.size();
  for (const Sphere& s : scene.spheres) d << s.center << s.radius << s.material;
  d << scene.planes.size();
  for (const Plane& p : scene.planes) d << p.point << p.normal << p.material;
  d << scene.quads.size();
  for (const Quad& q : scene.quads) d << q.corner << q.edge_u << q.edge_v << q.material;
  d << scene.triangles.size();
  for (const Triangle& t : scene.triangles) d << t.a << t.b << t.c << t.material;
  d << scene.lights.size();
  for (const PointLight& l : scene.lights) d << l.position << l.intensity;
  d << scene.area_lights.size();
  for (const QuadLight& l : scene.area_lights) d << l.shape.corner << l.shape.edge_u << l.shape.edge_v << l.intensity;
  return hex(d.h);
}

}  // namespace gi
