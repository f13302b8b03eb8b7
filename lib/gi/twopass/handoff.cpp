#include "gi/twopass/handoff.hpp"

#include <stdexcept>

#include "gi/core/not_implemented.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

namespace {

// Gouraud: the vertex values blended bilinearly at the point's (s, t) on its element.
Color at_point(const Mesh& mesh, const std::vector<Color>& vertex_values, int element, const vec3& point) {
  const Element& e = mesh.elements.at(element);
  const vec2 st = unbilinear(e.shape.corners, e.shape.normal, point);
  const auto& v = e.vertices;
  return (1 - st.x) * (1 - st.y) * vertex_values[v[0]] + st.x * (1 - st.y) * vertex_values[v[1]] +
         st.x * st.y * vertex_values[v[2]] + (1 - st.x) * st.y * vertex_values[v[3]];
}

}  // namespace

RadiosityHandoff make_handoff(Mesh mesh, std::vector<Color> B, std::vector<Color> D) {
  if (B.size() != mesh.elements.size() || D.size() != B.size())
    throw std::invalid_argument("two-pass hand-off: one B and one D per element");
  const std::size_t n = B.size();
  std::vector<Color> reflected(n), indirect(n);
  // BEGIN EXERCISE 16.1 the hand-off: what the eye pass reads from the mesh
  for (std::size_t i = 0; i < n; ++i) {
    const Color E = mesh.emission(mesh.elements[i]);
    reflected[i] = B[i] - E;        // a gather ray's reading: the lights' E is the shadow rays'
    indirect[i] = B[i] - E - D[i];  // the eye's reading: D too is the shadow rays'
  }
  // END EXERCISE 16.1
  RadiosityHandoff handoff{std::move(mesh), std::move(B), std::move(D), {}, {}};
  handoff.vertex_reflected = vertex_radiosity(handoff.mesh, reflected);
  handoff.vertex_indirect = vertex_radiosity(handoff.mesh, indirect);
  return handoff;
}

Color reflected_radiosity_at(const RadiosityHandoff& handoff, int element, const vec3& point) {
  return at_point(handoff.mesh, handoff.vertex_reflected, element, point);
}

Color indirect_radiosity_at(const RadiosityHandoff& handoff, int element, const vec3& point) {
  return at_point(handoff.mesh, handoff.vertex_indirect, element, point);
}

}  // namespace gi
