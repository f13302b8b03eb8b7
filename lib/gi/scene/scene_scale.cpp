#include "gi/scene/scene_scale.hpp"

#include <algorithm>

#include "gi/core/math.hpp"
#include "gi/core/norms.hpp"

namespace gi {

namespace {

double largest(const vec3& p) { return max_component(glm::abs(p)); }

double largest(const Quad& q) {
  return std::max({largest(q.corner), largest(q.corner + q.edge_u), largest(q.corner + q.edge_v),
                   largest(q.corner + q.edge_u + q.edge_v)});
}

}  // namespace

double scene_scale(const Scene& scene) {
  double m = largest(scene.camera.eye);
  for (const Sphere& s : scene.spheres) m = std::max(m, largest(s.center) + s.radius);
  for (const Plane& p : scene.planes) m = std::max(m, largest(p.point));
  for (const Quad& q : scene.quads) m = std::max(m, largest(q));
  for (const Triangle& t : scene.triangles) m = std::max({m, largest(t.a), largest(t.b), largest(t.c)});
  for (const PointLight& l : scene.lights) m = std::max(m, largest(l.position));
  for (const QuadLight& l : scene.area_lights) m = std::max(m, largest(l.shape));
  // m = f 2^e with f in [0.5, 1): the scale is 2^e, the inverse of norms.hpp's factor
  // (exact: both are powers of two); 1 for an empty scene.
  return 1 / power_of_two_scale(m);
}

}  // namespace gi
