#include "gi/radiosity/display/display.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

Image render_radiosity(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                       const Camera& camera, const DisplaySettings& settings) {
  return render_radiosity_picture(scene, mesh, B, camera, settings).shown;
}

std::string describe_pixel_samples(const DisplaySettings& settings) {
  const std::string n = std::to_string(settings.samples);
  return n + " x " + n + " jittered eye rays, box filter";
}

RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const Camera& camera, const DisplaySettings& settings) {
  if (B.size() != mesh.elements.size()) throw std::invalid_argument("radiosity display: one B per element");
  return render_radiosity_picture(scene, mesh, B,
                                  settings.shading == Shading::Smooth ? vertex_radiosity(mesh, B) : std::vector<Color>(),
                                  camera, settings);
}

RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const std::vector<Color>& vertex_B, const Camera& camera,
                                          const DisplaySettings& settings) {
  if (B.size() != mesh.elements.size() || scene.polygons().size() != mesh.elements.size())
    throw std::invalid_argument("radiosity display: one B per element, and a scene of the mesh's elements");
  if (settings.shading == Shading::Smooth && vertex_B.size() != mesh.vertices.size())
    throw std::invalid_argument("radiosity display: smooth shading needs one radiosity per vertex");
  if (settings.samples < 1 || settings.samples > 16) throw std::invalid_argument("display: samples must lie in [1, 16]");
  const CameraFrame frame = camera_frame(camera, settings.width, settings.height);
  RadiosityPicture picture{Image(settings.width, settings.height), Image(settings.width, settings.height)};
  const int n = settings.samples;
  parallel_for(settings.height, settings.threads, [&](int y) {
    for (int x = 0; x < settings.width; ++x) {
      Rng rng(settings.seed, static_cast<std::uint64_t>(y) * settings.width + x);
      Color sum(0.0), shown(0.0);
      for (int k = 0; k < n * n; ++k) {
        const double px = x + (k % n + rng.uniform()) / n, py = y + (k / n + rng.uniform()) / n;
        const Ray ray = primary_ray(frame, px, py);
        const auto hit = scene.first_hit(ray);
        if (!hit || !hit->front) continue;
        const Element& e = mesh.elements[hit->polygon];
        Color b = B[hit->polygon];
        if (settings.shading == Shading::Smooth) {
          const vec2 st = unbilinear(e.shape.corners, e.shape.normal, ray.at(hit->t));
          const auto& v = e.vertices;
          b = (1 - st.x) * (1 - st.y) * vertex_B[v[0]] + st.x * (1 - st.y) * vertex_B[v[1]] +
              st.x * st.y * vertex_B[v[2]] + (1 - st.x) * st.y * vertex_B[v[3]];
        }
        const Color radiance = b / pi;  // L = B / pi
        sum += radiance;
        shown += settings.white > 0 ? glm::min(radiance, Color(settings.white)) : radiance;
      }
      picture.radiance.at(x, y) = Pixel(sum / static_cast<double>(n * n));
      picture.shown.at(x, y) = Pixel(shown / static_cast<double>(n * n));
    }
  });
  return picture;
}

}  // namespace gi
