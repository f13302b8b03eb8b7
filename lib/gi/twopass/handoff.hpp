#pragma once
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"

namespace gi {

// The hand-off from the radiosity pass to the eye pass. In Heckbert's notation the
// radiosity pass computes L D* (light after any number of diffuse bounces, stored per
// element); the eye pass adds E S* (mirror and glass seen from the eye) and reads
// the mesh where an eye path first meets a diffuse surface. L S+ D paths -- caustics,
// light focused by the glass onto the floor -- belong to neither pass.
// The eye pass recomputes direct light by shadow rays, so what it reads must leave it
// out, or the direct light is counted twice:
//   B = E + D + B_indirect,   D_i = rho_i (mean of H over element i)  (the first bounce)
// Two readings, each interpolated bilinearly from the element's vertices (Gouraud):
//   indirect_radiosity_at   (B - E - D)(x)  what the eye pass adds to its shadow rays at
//                                            an eye ray's hit
//   reflected_radiosity_at  (B - E)(y)       what a final-gather ray reads where it lands:
//                                            the light y reflects, the lights' own E left
//                                            to the shadow rays
// Radiance is radiosity over pi (display.cpp): L = B / pi.
struct RadiosityHandoff {
  Mesh mesh;
  std::vector<Color> B;  // per element: the solution, E included
  std::vector<Color> D;  // per element: the direct part of B - E
  std::vector<Color> vertex_reflected;  // B - E at the mesh's vertices
  std::vector<Color> vertex_indirect;   // B - E - D at the mesh's vertices
};

// Throws std::invalid_argument unless there is one B and one D per element.
RadiosityHandoff make_handoff(Mesh mesh, std::vector<Color> B, std::vector<Color> D);

// The readings above at a point of element `element` (on its plane).
Color reflected_radiosity_at(const RadiosityHandoff& handoff, int element, const vec3& point);
Color indirect_radiosity_at(const RadiosityHandoff& handoff, int element, const vec3& point);

}  // namespace gi
