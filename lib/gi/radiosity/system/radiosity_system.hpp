#pragma once
#include <vector>

#include "gi/radiosity/system/form_factor_matrix.hpp"
#include "gi/radiosity/mesh/mesh.hpp"

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

// The spectral radius of R F for one colour channel: the factor by which Jacobi's
// error shrinks per iteration once the fast modes have died out (so ln(tol) / ln rho
// iterations to a tolerance tol), and the reason a closed room with rho near 1 takes
// so long. At most max_i rho_i * (row sum of F)_i: equal to the reflectance in a closed
// room of uniform rho, less wherever light escapes or is absorbed.
//
// Power iteration on R F + I (the shift makes the largest eigenvalue strictly
// dominant, also for two patches facing each other, whose eigenvalues come in +-
// pairs). For a positive x, every growth factor (R F x)_i / x_i brackets rho from one
// side (Collatz-Wielandt): the iteration stops when the smallest and the largest agree
// to `tolerance`, relative, over the elements x has not died out on (a row of zeros,
// which nothing reflects into, is left out).
struct SpectralRadius {
  double lower = 0, upper = 0;  // the smallest and largest growth factor of the last step
  int iterations = 0;
  bool converged = false;
  double value() const { return 0.5 * (lower + upper); }
};
SpectralRadius spectral_radius(const RadiositySystem& system, int channel, double tolerance = 1e-7,
                               int max_iterations = 20000);

}  // namespace gi
