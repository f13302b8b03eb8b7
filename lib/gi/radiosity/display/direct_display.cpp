#include "gi/radiosity/display/direct_display.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

std::vector<Color> indirect_part(const Mesh& mesh, const std::vector<Color>& B, const std::vector<Color>& D) {
  if (B.size() != mesh.elements.size() || D.size() != B.size())
    throw std::invalid_argument("indirect part: one B and one D per element");
  std::vector<Color> indirect(B.size());
  for (std::size_t i = 0; i < B.size(); ++i) indirect[i] = B[i] - mesh.emission(mesh.elements[i]) - D[i];
  return indirect;
}

Image render_direct_light(const FormFactorScene& scene, const Mesh& mesh, const Camera& camera,
                          const DisplaySettings& settings, const DirectLightSettings& direct) {
  if (scene.polygons().size() != mesh.elements.size())
    throw std::invalid_argument("direct light display: the scene must be built from the mesh's elements");
  if (settings.samples < 1 || settings.samples > 16) throw std::invalid_argument("display: samples must lie in [1, 16]");
  check(direct);
  const DirectLighting lights(mesh, direct.light_cells);
  const CameraFrame frame = camera_frame(camera, settings.width, settings.height);
  Image picture(settings.width, settings.height);
  const int n = settings.samples;
  parallel_for(settings.height, settings.threads, [&](int y) {
    for (int x = 0; x < settings.width; ++x) {
      // The display's eye rays, drawn from the same stream (display.cpp).
      Rng rng(settings.seed, static_cast<std::uint64_t>(y) * settings.width + x);
      Color sum(0.0);
      for (int k = 0; k < n * n; ++k) {
        const double px = x + (k % n + rng.uniform()) / n, py = y + (k / n + rng.uniform()) / n;
        const Ray ray = primary_ray(frame, px, py);
        const auto hit = scene.first_hit(ray);
        if (!hit || !hit->front) continue;
        const Element& e = mesh.elements[hit->polygon];
        // A hair above the surface, so that its own triangles do not shadow it.
        const vec3 point = ray.at(hit->t) + 1e-7 * length(e.shape.corners[2] - e.shape.corners[0]) * e.shape.normal;
        sum += (mesh.emission(e) + mesh.reflectance(e) * lights.irradiance(scene, point, e.shape.normal)) / pi;
      }
      picture.at(x, y) = Pixel(sum / static_cast<double>(n * n));
    }
  });
  return picture;
}

Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const std::vector<Color>& vertex_indirect,
                           const Camera& camera, const DisplaySettings& settings, const DirectLightSettings& direct) {
  Image picture = render_direct_light(scene, mesh, camera, settings, direct);
  const Image rest =
      render_radiosity_picture(scene, mesh, indirect_part(mesh, B, D), vertex_indirect, camera, settings).radiance;
  for (std::size_t i = 0; i < picture.pixels.size(); ++i) picture.pixels[i] += rest.pixels[i];
  return picture;
}

Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const Camera& camera, const DisplaySettings& settings,
                           const DirectLightSettings& direct) {
  const std::vector<Color> indirect = indirect_part(mesh, B, D);
  return render_split_picture(scene, mesh, B, D, vertex_radiosity(mesh, indirect), camera, settings, direct);
}

}  // namespace gi
