#include "gi/radiosity/display/direct_display.hpp"

#include <stdexcept>

#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

std::vector<Color> indirect_part(const Mesh& mesh, const std::vector<Color>& B, const std::vector<Color>& D) {
  if (B.size() != mesh.elements.size() || D.size() != B.size())
    throw std::invalid_argument("indirect part: one B and one D per element");
  std::vector<Color> indirect(B.size());
  for (std::size_t i = 0; i < B.size(); ++i) indirect[i] = B[i] - mesh.emission(mesh.elements[i]) - D[i];
  return indirect;
}

Color DirectRadiance::operator()(const Ray& ray, PixelSample&) const {
  const auto hit = scene.first_hit(ray);
  if (!hit || !hit->front) return Color(0.0);
  const Element& e = mesh.elements[hit->polygon];
  // A hair above the surface, so that its own triangles do not shadow it.
  const vec3 point = ray.at(hit->t) + 1e-7 * length(e.shape.corners[2] - e.shape.corners[0]) * e.shape.normal;
  return (mesh.emission(e) + mesh.reflectance(e) * lights.irradiance(scene, point, e.shape.normal)) / pi;
}

Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const std::vector<Color>& vertex_indirect,
                           const Camera& camera, const DisplaySettings& settings, const DirectLightSettings& direct,
                           std::uint64_t seed, int threads) {
  check(direct);
  const DirectLighting lights(mesh, direct.light_cells);
  const std::vector<Color> indirect = indirect_part(mesh, B, D);
  const MeshRadiance bounced{scene, mesh, indirect, vertex_indirect, settings.shading};
  check(bounced);
  const DirectRadiance first{scene, mesh, lights};
  DisplaySettings linear = settings;
  linear.white = 0;  // the radiance alone: no clamped picture to show
  return render_display(sum_of(first, bounced), camera, linear, seed, threads).radiance;
}

Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const Camera& camera, const DisplaySettings& settings,
                           const DirectLightSettings& direct, std::uint64_t seed, int threads) {
  return render_split_picture(scene, mesh, B, D, vertex_radiosity(mesh, indirect_part(mesh, B, D)), camera, settings,
                              direct, seed, threads);
}

}  // namespace gi
