// The lab's fixture: a closed unit cube [0, 1]^3 (radiosity_scenes.hpp's closed box),
// its faces cut into 4 x 4 elements, with radiosities chosen by hand, not solved for:
// each test sets B, E and D so that every mistake changes the answer.
#pragma once
#include <cmath>
#include <functional>
#include <vector>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/twopass/eye_world.hpp"
#include "gi/twopass/handoff.hpp"

namespace lab16 {

// The faces of closed_box(1): 0 the floor (y = 0), 1 the ceiling (y = 1), then the walls.
inline gi::Mesh room_mesh(bool with_ceiling = true) {
  std::vector<gi::Surface> faces = gi::closed_box(1.0).surfaces;
  if (!with_ceiling) faces.erase(faces.begin() + 1);
  return gi::make_mesh(faces, {0.25, 1});
}

// A hand-off whose values are given per element by f(surface, element centre).
using PerElement = std::function<gi::Color(int surface, const gi::vec3& centre)>;
inline gi::RadiosityHandoff room_handoff(const gi::Mesh& mesh, const PerElement& B, const PerElement& D,
                                         const PerElement& E) {
  gi::Mesh m = mesh;
  std::vector<gi::Color> b, d;
  for (const gi::Element& e : mesh.elements) {
    m.surfaces[e.surface].emission = E(e.surface, e.shape.centre);  // E is per surface
    b.push_back(B(e.surface, e.shape.centre));
    d.push_back(D(e.surface, e.shape.centre));
  }
  return gi::make_handoff(std::move(m), std::move(b), std::move(d));
}

inline gi::Color constant(double v) { return gi::Color(v); }

// The form factor from a point to a parallel rectangle of sides a x b at height h,
// the point under one of its corners (Siegel and Howell):
//   F = 1/(2 pi) [ A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2)) ],  A = a/h, B = b/h
inline double point_to_corner_rectangle(double a, double b, double h) {
  const double A = a / h, B = b / h, pi = 3.14159265358979323846;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * pi);
}

}  // namespace lab16
