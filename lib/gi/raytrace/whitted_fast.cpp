#include "gi/raytrace/whitted_fast.hpp"

#include "gi/accel/world_fast.hpp"
#include "gi/raytrace/light_sample_numbers.hpp"
#include "gi/raytrace/shading.hpp"

namespace gi {

namespace {

// A copy of a vector the caller has just written, read one double at a time.
// closest_hit writes its Hit double by double, and a plain copy reads two doubles at
// once: the processor cannot hand one 16-byte read the data of two 8-byte writes still
// on their way to the cache, and the read waits until they get there (the stall of
// world_fast.cpp). perf put 3% of the s10 render on reading the hit point. `volatile`
// keeps the compiler from merging the reads.
vec3 read_double_by_double(const vec3& v) {
  const volatile vec3& from = v;
  return vec3(from.x, from.y, from.z);
}

}  // namespace

// Kept out of the recursive trace() (noinline) so that trace's stack frame stays small;
// flatten builds shadow_ray, phong and diffuse_at into it (with shadow_ray called from
// two places below the compiler would call it, and copying the ray it wrote to memory
// would stall as read_double_by_double explains).
[[gnu::noinline, gnu::flatten]] Color shade_locally_fast(const World& world, const Hit& hit, const vec3& n,
                                                         const vec3& to_eye, const TraceSettings& settings,
                                                         RayCounts& counts, PixelSample& sample, int depth) {
  const vec3 point = read_double_by_double(hit.point);
  const Material& material = world.scene.materials[hit.material];
  const Color kd = diffuse_at(material, point);
  Color colour = material.emission + material.ambient * kd * world.scene.ambient_light;
  const double epsilon = settings.epsilon * world.scale;  // relative to the scene's size (scene_scale.hpp)
  // Each shadow ray begins with a square root and a division in a chain (shadow_ray),
  // about 30 cycles that its sphere tests wait for. So the next light's ray is made
  // before this light's is traced: the processor works out the next chain during the
  // trace instead of after it. The same operations as one light at a time: same bytes.
  const std::vector<PointLight>& lights = world.scene.lights;
  Ray next = lights.empty() ? Ray{} : shadow_ray(point, n, lights[0].position, epsilon);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const Ray shadow = next;
    if (i + 1 < lights.size()) next = shadow_ray(point, n, lights[i + 1].position, epsilon);
    const vec3& l = shadow.direction;
    if (dot(n, l) <= 0) continue;  // light behind the surface: no shadow ray needed
    counts.count(RayKind::Shadow, depth);
    if (!any_hit_fast(world, shadow)) colour += phong(material, kd, n, l, to_eye, lights[i].intensity);
  }
  const std::vector<QuadLight>& area_lights = world.scene.area_lights;
  for (std::size_t l = 0; l < area_lights.size(); ++l) {
    const QuadLight& light = area_lights[l];
    const auto reaches = [&](const vec3& y) {  // S(x, y): does the shadow ray get to y?
      const Ray shadow = shadow_ray(point, n, y, epsilon);
      if (dot(n, shadow.direction) <= 0) return false;  // y is behind the surface
      counts.count(RayKind::Shadow, depth);
      return !any_hit_fast(world, shadow);
    };
    const auto point_light_at = [&](const vec3& y) {
      return phong(material, kd, n, normalize(y - point), to_eye, light.intensity);
    };
    const std::uint32_t dimension = shadow_dimension(depth, int(l), int(area_lights.size()));
    colour += soft_shadow_estimate(light, light_samples(settings.soft_shadows, sample, dimension), reaches,
                                   point_light_at);
  }
  return colour;
}

}  // namespace gi
