#include "gi/radiosity/display/display.hpp"

#include <stdexcept>

#include "gi/image/diff.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

void check(const MeshRadiance& r) {
  if (r.B.size() != r.mesh.elements.size() || r.scene.polygons().size() != r.mesh.elements.size())
    throw std::invalid_argument("radiosity display: one B per element, and a scene of the mesh's elements");
  if (r.shading == Shading::Smooth && r.vertex_B.size() != r.mesh.vertices.size())
    throw std::invalid_argument("radiosity display: smooth shading needs one radiosity per vertex");
}

Color MeshRadiance::operator()(const Ray& ray, PixelSample&) const {
  const auto hit = scene.first_hit(ray);
  if (!hit || !hit->front) return Color(0.0);
  const Element& e = mesh.elements[hit->polygon];
  Color b = B[hit->polygon];
  if (shading == Shading::Smooth) {
    const vec2 st = unbilinear(e.shape.corners, e.shape.normal, ray.at(hit->t));
    const auto& v = e.vertices;
    b = (1 - st.x) * (1 - st.y) * vertex_B[v[0]] + st.x * (1 - st.y) * vertex_B[v[1]] +
        st.x * st.y * vertex_B[v[2]] + (1 - st.x) * st.y * vertex_B[v[3]];
  }
  return b / pi;  // L = B / pi
}

std::string describe_pixel_samples(const DisplaySettings& settings) {
  return describe_pixel_samples(settings.sampling());
}

RadiosityPicture render_display(RadianceFunction radiance, const Camera& camera, const DisplaySettings& settings,
                                std::uint64_t seed, int threads) {
  if (settings.samples < 1 || settings.samples > 16) throw std::invalid_argument("display: samples must lie in [1, 16]");
  Film film = make_film(settings.width, settings.height, seed);
  render_pass(film, camera, settings.sampling(), radiance, threads);
  RadiosityPicture picture{film_mean(film), {}};
  if (settings.white > 0) {
    // The same eye rays again (a fresh film of the same seed), each clamped.
    Film shown = make_film(settings.width, settings.height, seed);
    render_pass(shown, camera, settings.sampling(), clamped(radiance, settings.white), threads);
    picture.shown = film_mean(shown);
  } else {
    picture.shown = picture.radiance;
  }
  return picture;
}

RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const Camera& camera, const DisplaySettings& settings, std::uint64_t seed,
                                          int threads) {
  if (B.size() != mesh.elements.size()) throw std::invalid_argument("radiosity display: one B per element");
  return render_radiosity_picture(scene, mesh, B,
                                  settings.shading == Shading::Smooth ? vertex_radiosity(mesh, B) : std::vector<Color>(),
                                  camera, settings, seed, threads);
}

RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const std::vector<Color>& vertex_B, const Camera& camera,
                                          const DisplaySettings& settings, std::uint64_t seed, int threads) {
  const MeshRadiance radiance{scene, mesh, B, vertex_B, settings.shading};
  check(radiance);
  return render_display(radiance, camera, settings, seed, threads);
}

Image solutions_grid(const Mesh& mesh, const std::vector<std::vector<Color>>& solutions, int columns,
                     const Camera& camera, int size, std::uint64_t seed, int threads) {
  const FormFactorScene scene(element_shapes(mesh));
  DisplaySettings settings;
  settings.width = settings.height = size;
  settings.white = 1;  // anti-aliased edges on the light (DisplaySettings::white)
  std::vector<Image> pictures;
  for (const std::vector<Color>& B : solutions)
    pictures.push_back(render_radiosity_picture(scene, mesh, B, camera, settings, seed, threads).shown);
  return image_grid(pictures, columns);
}

}  // namespace gi
