#include "gi/pathtrace/lights.hpp"

#include <stdexcept>

#include "gi/core/onb.hpp"

namespace gi {

namespace {

bool emits(const Material& m) { return max_component(m.emission) > 0; }

double triangle_area(const Triangle& t) { return 0.5 * length(cross(t.b - t.a, t.c - t.a)); }

// A sphere seen from x outside it shows the cap of directions from its centre within
// theta_max of the way to x, cos(theta_max) = r / d: the tangent cone from x touches
// the sphere exactly there. The cap's area is 2 pi r^2 (1 - r / d).
double cap_cos_max(const Sphere& s, const vec3& x) { return s.radius / length(x - s.center); }

}  // namespace

Lights find_lights(Scene& scene) {
  for (const Material& m : scene.materials)
    if (std::min({m.emission.x, m.emission.y, m.emission.z}) < 0)
      throw std::invalid_argument("material '" + m.name + "': emission must be >= 0");
  for (const Plane& p : scene.planes)
    if (emits(scene.materials[p.material]))
      throw std::invalid_argument("an emitting plane has infinite power: make the light a quad or a sphere");
  Lights lights;
  std::vector<int> materials;  // each light's
  // Each emitter gets its own copy of its material, so that hit.material names the light.
  const auto add = [&](Light::Shape shape, int index, int& material, double area) {
    const Material copy = scene.materials[material];
    material = scene.add(copy);
    materials.push_back(material);
    lights.lights.push_back({shape, index, copy.emission, area});
  };
  for (std::size_t i = 0; i < scene.triangles.size(); ++i)
    if (emits(scene.materials[scene.triangles[i].material]))
      add(Light::Shape::Triangle, int(i), scene.triangles[i].material, triangle_area(scene.triangles[i]));
  for (std::size_t i = 0; i < scene.quads.size(); ++i)
    if (emits(scene.materials[scene.quads[i].material]))
      add(Light::Shape::Quad, int(i), scene.quads[i].material, area(scene.quads[i]));
  for (std::size_t i = 0; i < scene.spheres.size(); ++i)
    if (emits(scene.materials[scene.spheres[i].material]))
      add(Light::Shape::Sphere, int(i), scene.spheres[i].material,
          4 * pi * scene.spheres[i].radius * scene.spheres[i].radius);

  lights.of_material.assign(scene.materials.size(), -1);
  std::vector<double> power;
  for (std::size_t k = 0; k < lights.lights.size(); ++k) {
    lights.of_material[materials[k]] = static_cast<int>(k);
    // pi A L_e: > 0, since every channel weighs in the luminance
    power.push_back(pi * lights.lights[k].area * luminance(lights.lights[k].radiance));
  }
  if (!power.empty()) lights.choice = make_discrete_distribution(power);
  return lights;
}

LightSample sample_light(const Lights& lights, const Scene& scene, const vec3& x, double u_choice, vec2 u) {
  const int k = sample_discrete(lights.choice, u_choice);
  const Light& light = lights.lights[k];
  const double p_choice = discrete_pdf(lights.choice, k);
  switch (light.shape) {
    case Light::Shape::Triangle: {
      const Triangle& t = scene.triangles[light.index];
      const vec3 b = sample_uniform_triangle(u);
      return {b.x * t.a + b.y * t.b + b.z * t.c, normalize(cross(t.b - t.a, t.c - t.a)), light.radiance,
              p_choice * uniform_triangle_pdf(light.area), k};
    }
    case Light::Shape::Quad: {
      const Quad& q = scene.quads[light.index];
      return {q.corner + u.x * q.edge_u + u.y * q.edge_v, normal(q), light.radiance, p_choice / light.area, k};
    }
    case Light::Shape::Sphere: {
      const Sphere& s = scene.spheres[light.index];
      const double d = length(x - s.center);
      if (d <= s.radius) {  // inside: every point faces away, but the density must still be right
        const vec3 w = sample_uniform_sphere(u);
        return {s.center + s.radius * w, w, light.radiance, p_choice / light.area, k};
      }
      // Uniform over the visible cap, by area: directions from the centre, uniform in
      // the cone towards x, p_A = p_cone / r^2.
      const double cos_max = cap_cos_max(s, x);
      const vec3 w = Onb((x - s.center) / d).to_world(sample_uniform_cone(u, cos_max));
      return {s.center + s.radius * w, w, light.radiance, p_choice * uniform_cone_pdf(cos_max) / (s.radius * s.radius),
              k};
    }
  }
  throw std::logic_error("sample_light: unknown light shape");
}

double light_pdf_area(const Lights& lights, const Scene& scene, int k, const vec3& x) {
  const Light& light = lights.lights[k];
  const double p_choice = discrete_pdf(lights.choice, k);
  if (light.shape != Light::Shape::Sphere) return p_choice / light.area;
  const Sphere& s = scene.spheres[light.index];
  if (length(x - s.center) <= s.radius) return p_choice / light.area;
  return p_choice * uniform_cone_pdf(cap_cos_max(s, x)) / (s.radius * s.radius);
}

}  // namespace gi
