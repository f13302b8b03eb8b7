#include "gi/radiosity/mesh/mesh.hpp"

#include <algorithm>
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
// Capped past 10^6, which no mesh may pass anyway, so that the cast cannot overflow.
int pieces(double length, double patch_size) {
  return static_cast<int>(std::clamp(std::ceil(length / patch_size - 1e-9), 1.0, 1e6 + 1));
}

// Patches along the two edge pairs of a surface: make_mesh's grid, and element_count's.
std::array<int, 2> patch_grid(const std::array<vec3, 4>& c, double patch_size) {
  return {pieces(std::max(length(c[1] - c[0]), length(c[2] - c[3])), patch_size),
          pieces(std::max(length(c[3] - c[0]), length(c[2] - c[1])), patch_size)};
}

}  // namespace

Mesh make_mesh(const std::vector<Surface>& surfaces, const MeshSettings& settings) {
  if (!(settings.patch_size > 0)) throw std::invalid_argument("mesh: the patch size must be > 0");
  if (settings.elements_per_side < 1 || settings.elements_per_side > 64)
    throw std::invalid_argument("mesh: elements per patch side must lie in [1, 64]");
  for (const Surface& s : surfaces) check(s);
  // Counted before anything is made: the same grid as below.
  if (element_count(surfaces, settings) > 1e6)
    throw std::invalid_argument("mesh: more than 10^6 elements; use a larger patch size");
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
    const auto [nu, nv] = patch_grid(c, settings.patch_size);
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

double element_count(const std::vector<Surface>& surfaces, const MeshSettings& settings) {
  double n = 0;
  for (const Surface& s : surfaces) {
    const auto [nu, nv] = patch_grid(s.corners, settings.patch_size);
    n += double(nu) * nv * settings.elements_per_side * settings.elements_per_side;
  }
  return n;
}

double patch_size_at_most(const std::vector<Surface>& surfaces, int elements, int elements_per_side, int most) {
  const double about = patch_size_for(surfaces, elements, elements_per_side);
  if (element_count(surfaces, {about, elements_per_side}) <= most) return about;
  // Each surface rounds its patches up, so the count can pass `elements`; it falls as the
  // patch size grows, down to one patch per surface at the longest edge.
  double longest = 0;
  for (const Surface& s : surfaces)
    for (int k = 0; k < 4; ++k) longest = std::max(longest, length(s.corners[(k + 1) % 4] - s.corners[k]));
  double hi = 2 * longest;
  if (element_count(surfaces, {hi, elements_per_side}) > most)
    throw std::invalid_argument("mesh: " + std::to_string(surfaces.size()) + " surfaces of " +
                                std::to_string(elements_per_side * elements_per_side) +
                                " elements at least each make more than " + std::to_string(most) + " elements");
  // Bisection for the smallest size that fits: the finest mesh within the limit.
  double lo = about;
  for (int step = 0; step < 100 && hi - lo > 1e-12 * hi; ++step) {
    const double mid = 0.5 * (lo + hi);
    (element_count(surfaces, {mid, elements_per_side}) <= most ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace gi
