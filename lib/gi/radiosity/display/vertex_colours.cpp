#include "gi/radiosity/display/vertex_colours.hpp"

#include <stdexcept>

#include "gi/core/atomic_file.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/image/image_io.hpp"

namespace gi {

std::vector<Color> vertex_radiosity(const Mesh& mesh, const std::vector<Color>& B) {
  if (B.size() != mesh.elements.size()) throw std::invalid_argument("vertex radiosity: one B per element");
  // BEGIN EXERCISE 8.1 vertex colours from element radiosities
  std::vector<Color> sum(mesh.vertices.size(), Color(0.0));
  std::vector<double> weight(mesh.vertices.size(), 0.0);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    for (int v : element.vertices) {
      sum[v] += element.shape.area * B[e];
      weight[v] += element.shape.area;
    }
  }
  for (std::size_t v = 0; v < sum.size(); ++v)
    if (weight[v] > 0) sum[v] /= weight[v];
  return sum;
  // END EXERCISE 8.1
}

void write_ply(const Mesh& mesh, const std::vector<Color>& vertex_B, double exposure,
               const std::filesystem::path& file) {
  std::vector<std::vector<int>> faces;
  for (const Element& e : mesh.elements) faces.push_back({e.vertices.begin(), e.vertices.end()});
  write_ply(mesh, vertex_B, exposure, file, faces);
}

void write_ply(const Mesh& mesh, const std::vector<Color>& vertex_B, double exposure, const std::filesystem::path& file,
               const std::vector<std::vector<int>>& faces) {
  if (vertex_B.size() != mesh.vertices.size()) throw std::invalid_argument("PLY: one colour per vertex");
  for (const std::vector<int>& face : faces) {
    bool valid = face.size() >= 3 && face.size() <= 255;
    for (int v : face) valid = valid && v >= 0 && v < static_cast<int>(mesh.vertices.size());
    if (!valid) throw std::invalid_argument("PLY: a face needs 3 to 255 corners, each a vertex of the mesh");
  }
  for (const Color& b : vertex_B)  // a garbage mesh is never written silently
    if (!is_finite(b)) throw std::runtime_error("refusing to write " + file.string() + ": a vertex radiosity is NaN or infinite");
  const auto byte = [&](double b) {
    return static_cast<int>(std::lround(255 * srgb_encode(std::clamp(exposure * b / pi, 0.0, 1.0))));
  };
  write_atomically(file, [&](std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment gi-workbench radiosity: vertex colour = sRGB(exposure * B / pi)\n"
        << "element vertex " << mesh.vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        << "element face " << faces.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const vec3& p = mesh.vertices[v];
      out << p.x << ' ' << p.y << ' ' << p.z << ' ' << byte(vertex_B[v].x) << ' ' << byte(vertex_B[v].y) << ' '
          << byte(vertex_B[v].z) << '\n';
    }
    for (const std::vector<int>& face : faces) {
      out << face.size();
      for (int v : face) out << ' ' << v;
      out << '\n';
    }
  });
}

}  // namespace gi
