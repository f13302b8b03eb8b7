#pragma once
#include <cstdint>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/system/solver.hpp"
#include "gi/twopass/handoff.hpp"
#include "gi/twopass/two_pass_scene.hpp"

namespace gi {

// Pass 1: progressive radiosity on the diffuse surfaces, the view-independent part.
//  - The direct part D_i = rho_i (1/A_i) integral of H over element i, with H from
//    shadow rays (shadow_rays.hpp) cast into everything, spheres included: the spheres
//    shadow the radiosity's first bounce exactly as they shadow the eye pass's.
//  - The rest, B' = D + R F B' (direct_light.hpp's split), by progressive refinement
//    with form factors between the mesh's elements only: the radiosity pass cannot
//    hold a mirror or glass, so for the light that has already bounced the spheres are
//    not there at all (they neither block nor reflect it). A small error near the
//    spheres, which the final gather -- whose rays do stop at the spheres -- removes
//    from what the eye sees first hand.
//  - B = E + B'.
struct RadiosityPassSettings {
  int elements = 1000;        // about how many (patch_size_for), one element per patch
  int light_cells = 4;        // D: cells^2 shadow rays per light and point
  int receiver_strata = 2;    // D: strata^2 jittered points per element
  FormFactorSettings form_factors;  // the interreflection's; hemicube_resolution 0: from the mesh
  double tolerance = 1e-4;    // progressive refinement's, on the unshot energy
  std::uint64_t seed = 1;     // element i's points draw from stream i
};

struct RadiosityPass {
  RadiosityHandoff handoff;
  SolveStatus status = SolveStatus::StoppedAtLimit;
  int shots = 0;
  int hemicube_resolution = 0;
  double direct_seconds = 0, solve_seconds = 0;  // D; the form factors and shots
  double seconds() const { return direct_seconds + solve_seconds; }
};

// D is shared among `threads` threads (0 = all cores): the same for any number.
// Throws std::invalid_argument for bad settings or a bad scene (make_mesh's messages).
RadiosityPass radiosity_pass(const TwoPassScene& scene, const RadiosityPassSettings& settings, int threads);

}  // namespace gi
