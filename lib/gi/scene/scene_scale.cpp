#include "gi/scene/scene_scale.hpp"

#include <cmath>

namespace gi {

namespace {

double largest(const vec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

}  // namespace

double scene_scale(const Scene& scene) {
  double m = largest(scene.camera.eye);
  for (const Sphere& s : scene.spheres) m = std::max(m, largest(s.center) + s.radius);
  for (const Plane& p : scene.planes) m = std::max(m, largest(p.point));
  for (const Quad& q : scene.quads)
    m = std::max({m, largest(q.corner), largest(q.corner + q.edge_u), largest(q.corner + q.edge_v),
                  largest(q.corner + q.edge_u + q.edge_v)});
  for (const Triangle& t : scene.triangles) m = std::max({m, largest(t.a), largest(t.b), largest(t.c)});
  for (const PointLight& l : scene.lights) m = std::max(m, largest(l.position));
  for (const QuadLight& l : scene.area_lights) {
    const Quad& q = l.shape;
    m = std::max({m, largest(q.corner), largest(q.corner + q.edge_u), largest(q.corner + q.edge_v),
                  largest(q.corner + q.edge_u + q.edge_v)});
  }
  if (!(m > 0) || !std::isfinite(m)) return 1;
  int e = 0;
  (void)std::frexp(m, &e);  // m = f 2^e, f in [0.5, 1)
  return std::ldexp(1.0, e);
}

}  // namespace gi
