#pragma once
#include <vector>

#include "gi/radiosity/form_factor_matrix.hpp"
#include "gi/radiosity/mesh.hpp"

namespace gi {

// The radiosity equation of every element i, one per colour channel:
//   B_i = E_i + rho_i sum_j F_ij B_j,      i.e. (I - R F) B = E
// with R = diag(rho). B and E are radiant exitances (W/m^2); rho in [0, 1] for
// physical surfaces. Areas are kept for reciprocity (F_ji = F_ij A_i / A_j) and for
// energies (A_i B_i is the power leaving element i).
struct RadiositySystem {
  std::vector<double> area;     // A_i
  std::vector<Color> rho;       // rho_i
  std::vector<Color> emission;  // E_i
  FormFactorMatrix F;           // F_ij, element to element

  int size() const { return static_cast<int>(area.size()); }
};

// The system of a mesh's elements with the given form factors -- or with none (an
// empty matrix) for progressive refinement, which computes its rows as it shoots.
// Throws std::invalid_argument when F's size matches neither.
RadiositySystem make_system(const Mesh& mesh, FormFactorMatrix F);

// The residual r = E - (I - R F) B = E + R F B - B: zero at the solution; r_i is the
// radiosity element i still lacks (the "unshot" radiosity of Southwell's method).
std::vector<Color> residual(const RadiositySystem& system, const std::vector<Color>& B);

// sum_i A_i B_i: the power leaving all elements (per channel).
Color power(const std::vector<double>& area, const std::vector<Color>& B);

}  // namespace gi
