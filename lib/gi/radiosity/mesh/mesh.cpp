#include "gi/radiosity/mesh/mesh.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/radiosity/mesh/overlaps.hpp"

namespace gi {

namespace {

void check(const Surface& s) {
  try {
    (void)make_polygon(s.corners);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("surface '" + s.name + "': " + e.what());
  }
  if (!is_finite(s.reflectance) || !is_finite(s.emission) || std::min({s.reflectance.x, s.reflectance.y,
                                                                        s.reflectance.z}) < 0 ||
      std::min({s.emission.x, s.emission.y, s.emission.z}) < 0)
    throw std::invalid_argument("surface '" + s.name + "': reflectance and emission must be finite and >= 0");
}

// How many pieces an edge pair of length up to `length` is cut into.
int pieces(double length, double patch_size) { return std::max(1, static_cast<int>(std::ceil(length / patch_size - 1e-9))); }

}  // namespace

Mesh make_mesh(const std::vector<Surface>& surfaces, const MeshSettings& settings) {
  if (!(settings.patch_size > 0)) throw std::invalid_argument("mesh: the patch size must be > 0");
  if (settings.elements_per_side < 1 || settings.elements_per_side > 64)
    throw std::invalid_argument("mesh: elements per patch side must lie in [1, 64]");
  for (const Surface& s : surfaces) check(s);
  // Surfaces that lie in one plane and overlap: few, so every pair is compared.
  std::vector<Polygon> shapes;
  for (const Surface& s : surfaces) shapes.push_back(make_polygon(s.corners));
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = i + 1; j < shapes.size(); ++j)
      if (overlapping(shapes[i], shapes[j]))
        throw std::invalid_argument("surfaces '" + surfaces[i].name + "' and '" + surfaces[j].name +
                                    "' lie in one plane and overlap; remove one, or move it off the other");
  Mesh mesh;
  mesh.surfaces = surfaces;
  const int m = settings.elements_per_side;
  for (int s = 0; s < static_cast<int>(surfaces.size()); ++s) {
    const std::array<vec3, 4>& c = surfaces[s].corners;
    const int nu = pieces(std::max(length(c[1] - c[0]), length(c[2] - c[3])), settings.patch_size);
    const int nv = pieces(std::max(length(c[3] - c[0]), length(c[2] - c[1])), settings.patch_size);
    if (static_cast<double>(nu) * nv * m * m + mesh.elements.size() > 1e6)
      throw std::invalid_argument("mesh: more than 10^6 elements; use a larger patch size");
    // The surface's grid of element corners, shared by neighbouring elements.
    const int first_vertex = static_cast<int>(mesh.vertices.size());
    const int NU = nu * m, NV = nv * m;
    for (int j = 0; j <= NV; ++j)
      for (int i = 0; i <= NU; ++i) mesh.vertices.push_back(bilinear(c, double(i) / NU, double(j) / NV));
    const auto vertex = [&](int i, int j) { return first_vertex + j * (NU + 1) + i; };
    for (int pv = 0; pv < nv; ++pv)
      for (int pu = 0; pu < nu; ++pu) {
        const int i0 = pu * m, j0 = pv * m;
        const std::array<vec3, 4> corners = {mesh.vertices[vertex(i0, j0)], mesh.vertices[vertex(i0 + m, j0)],
                                             mesh.vertices[vertex(i0 + m, j0 + m)], mesh.vertices[vertex(i0, j0 + m)]};
        const int patch = static_cast<int>(mesh.patches.size());
        mesh.patches.push_back({make_polygon(corners), s, static_cast<int>(mesh.elements.size()), m * m});
        for (int ev = 0; ev < m; ++ev)
          for (int eu = 0; eu < m; ++eu) {
            const int i = i0 + eu, j = j0 + ev;
            const std::array<int, 4> v = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
            const Polygon shape = make_polygon({mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]],
                                                mesh.vertices[v[3]]});
            mesh.elements.push_back({shape, s, patch, v});
          }
      }
  }
  return mesh;
}

std::vector<Polygon> element_shapes(const Mesh& mesh) {
  std::vector<Polygon> shapes;
  shapes.reserve(mesh.elements.size());
  for (const Element& e : mesh.elements) shapes.push_back(e.shape);
  return shapes;
}

double patch_size_for(const std::vector<Surface>& surfaces, int elements, int elements_per_side) {
  if (elements < 1) throw std::invalid_argument("mesh: the element count must be >= 1");
  double area = 0;
  for (const Surface& s : surfaces) area += make_polygon(s.corners).area;
  // n elements of side e cover the area: e = sqrt(area / n); a patch is m elements wide.
  return std::sqrt(area / elements) * elements_per_side;
}

}  // namespace gi
