#include "gi/radiosity/form_factors/direct_light.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"

namespace gi {

void check(const DirectLightSettings& s) {
  if (s.light_cells < 1 || s.light_cells > 64)
    throw std::invalid_argument("direct light: light cells must lie in [1, 64], got " + std::to_string(s.light_cells));
  if (s.receiver_points < 1 || s.receiver_points > 8)
    throw std::invalid_argument("direct light: receiver points must lie in [1, 8], got " +
                                std::to_string(s.receiver_points));
}

DirectLighting::DirectLighting(const Mesh& mesh, int cells) {
  check(DirectLightSettings{cells, 1});
  for (const Surface& s : mesh.surfaces) {
    if (max_component(s.emission) <= 0) continue;
    Light light{make_polygon(s.corners), s.emission, {}};
    for (int a = 0; a < cells; ++a)
      for (int b = 0; b < cells; ++b) {
        auto at = [&](int da, int db) { return bilinear(s.corners, double(a + da) / cells, double(b + db) / cells); };
        const Polygon cell = make_polygon({at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
        light.cells.push_back({cell.centre, cell.area});
      }
    lights_.push_back(std::move(light));
  }
}

// The visible fraction of `light` from x: each cell weighted by its differential
// form factor cos_x cos_c A_c / (pi r^2) (the pi cancels in the ratio).
double DirectLighting::visible_fraction(const FormFactorScene& scene, const vec3& x, const vec3& n,
                                        const Light& light) const {
  double seen = 0, all = 0;
  for (const Cell& c : light.cells) {
    const vec3 d = c.centre - x;
    const double r2 = dot(d, d);
    const double f = dot(n, d) * -dot(light.shape.normal, d) * c.area / (r2 * r2);
    if (!(f > 0)) continue;  // the cell is behind x or faces away
    all += f;
    if (scene.visible(x, c.centre)) seen += f;
  }
  return all > 0 ? seen / all : 0.0;
}

// H(x) = sum_l E_l F(x -> l) V(x, l).
Color DirectLighting::irradiance(const FormFactorScene& scene, const vec3& x, const vec3& n) const {
  Color H(0.0);
  for (const Light& light : lights_) {
    const double F = form_factor_point_to_polygon(x, n, light.shape);
    if (F > 0) H += light.exitance * (F * visible_fraction(scene, x, n, light));
  }
  return H;
}

Color direct_radiosity(const DirectLighting& lights, const FormFactorScene& scene, const Polygon& p, const Color& rho,
                       int points) {
  if (max_component(rho) <= 0) return Color(0.0);
  const GaussRule& rule = gauss_legendre(points);
  // Receiver points on the element's plane through its lifted centre, a hair above:
  // no part of a slightly twisted element then blocks its own shadow rays.
  const vec3 plane = lifted_centre(p) + 1e-7 * length(p.corners[2] - p.corners[0]) * p.normal;
  const auto& c = p.corners;
  Color integral(0.0);
  double area = 0;
  for (int u = 0; u < points; ++u)
    for (int v = 0; v < points; ++v) {
      const double s = rule.nodes[u], t = rule.nodes[v];
      const vec3 on_surface = bilinear(c, s, t);
      const vec3 x = on_surface + dot(plane - on_surface, p.normal) * p.normal;
      // dA = |dx/ds x dx/dt| ds dt on the bilinear map (not constant unless a parallelogram).
      const vec3 dx_ds = (1 - t) * (c[1] - c[0]) + t * (c[2] - c[3]);
      const vec3 dx_dt = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
      const double w = rule.weights[u] * rule.weights[v] * length(cross(dx_ds, dx_dt));
      integral += w * lights.irradiance(scene, x, p.normal);
      area += w;
    }
  return rho * (integral / area);
}

std::vector<Color> direct_radiosity(const FormFactorScene& scene, const Mesh& mesh,
                                    const DirectLightSettings& settings, int threads) {
  check(settings);
  if (scene.polygons().size() != mesh.elements.size())
    throw std::invalid_argument("direct light: the scene must be built from the mesh's elements");
  const DirectLighting lights(mesh, settings.light_cells);
  std::vector<Color> D(mesh.elements.size(), Color(0.0));
  parallel_for(static_cast<int>(mesh.elements.size()), threads, [&](int i) {
    const Element& e = mesh.elements[i];
    D[i] = direct_radiosity(lights, scene, e.shape, mesh.reflectance(e), settings.receiver_points);
  });
  return D;
}

RadiositySystem indirect_system(RadiositySystem system, const std::vector<Color>& D) {
  if (static_cast<int>(D.size()) != system.size())
    throw std::invalid_argument("indirect system: one direct radiosity per element is needed");
  system.emission = D;
  return system;
}

std::vector<Color> with_emission(const RadiositySystem& system, std::vector<Color> B_indirect) {
  if (static_cast<int>(B_indirect.size()) != system.size())
    throw std::invalid_argument("with_emission: one radiosity per element is needed");
  for (int i = 0; i < system.size(); ++i) B_indirect[i] += system.emission[i];
  return B_indirect;
}

}  // namespace gi
