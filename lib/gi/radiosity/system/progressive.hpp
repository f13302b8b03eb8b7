#pragma once
#include <functional>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/solver.hpp"

namespace gi {

// Progressive refinement (Cohen, Chen, Wallace and Greenberg 1988): instead of every
// element gathering, the patch with the most unshot power shoots it to every
// element. Only that patch's row of form factors is needed, computed when it shoots
// (a hemicube), so no n x n matrix is stored, and after every shot the current B is
// a picture worth showing.
//
// Shooting from patch p, with unshot radiosity dB_p: element j receives
//   dB_j = rho_j dB_p F_pj A_p / A_j       (F_jp = F_pj A_p / A_j by reciprocity)
// which adds to its radiosity B_j and to its own unshot dB_j; then dB_p = 0.

// The form factors from patch p to every element, computed when p shoots.
using ShooterRow = std::function<std::vector<double>(int patch)>;

// The usual ShooterRow: patch p's row by `settings` (a hemicube at the patch's centre
// by default) against `receivers`, which must be built from element_shapes(mesh).
// It keeps references to `receivers` and `mesh`: they must outlive it.
ShooterRow patch_shooter(const FormFactorScene& receivers, const Mesh& mesh, const FormFactorSettings& settings);

// One shot from `patch`: its unshot radiosity dB_p is the area-weighted mean of its
// elements' unshot radiosities, which are cleared (shot); every element j then
// receives rho_j dB_p F_pj A_p / A_j into both its radiosity B_j and its unshot
// radiosity. F_p holds F_pj for every element j.
void shoot(const Patch& patch, const std::vector<double>& F_p, const std::vector<double>& area,
           const std::vector<Color>& rho, std::vector<Color>& B, std::vector<Color>& unshot);

// The ambient term, for display only: the light not yet shot, spread evenly and
// reflected again and again,
//   ambient = R_total * sum_i dB_i A_i / sum_i A_i,   R_total = 1 / (1 - rho_avg),
// with rho_avg the area-weighted mean reflectance (per channel). Shown as B_i +
// rho_i * ambient, it gives early pictures the right overall brightness.
Color ambient_term(const std::vector<double>& area, const std::vector<Color>& rho, const std::vector<Color>& unshot);

// B_i + rho_i * ambient for every element.
std::vector<Color> with_ambient(const std::vector<double>& area, const std::vector<Color>& rho,
                                const std::vector<Color>& B, const std::vector<Color>& unshot);

// The patch that shoots next: the one with the most unshot power sum_e dB_e A_e over
// its elements, added over the three channels (the first such patch on a tie). By
// power, not radiosity: a small bright patch holds less light than a large dim one.
int choose_shooter(const std::vector<Patch>& patches, const std::vector<double>& area,
                   const std::vector<Color>& unshot);

// Shoots from the mesh's patches (each the group of its elements; unshot radiosity
// is kept per element and a patch's is their area-weighted mean) until the unshot
// energy falls below options.tolerance or max_steps shots. system.F is not used.
SolverResult solve_progressive(const RadiositySystem& system, const Mesh& mesh, const ShooterRow& row,
                               const SolverOptions& options = {});

}  // namespace gi
