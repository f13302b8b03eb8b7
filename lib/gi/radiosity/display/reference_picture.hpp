#pragma once
#include <vector>

#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace gi {

// A picture of a radiosity scene to score radiosity solutions against, made by other
// means than the ones it scores: at the very point x each eye ray hits,
//   L(x) = [E(x) + rho(x) (D(x) + I(x))] / pi
//   D(x)  the direct light: sum over emitters of E_e F(x -> e) with visibility. Exact
//         (Lambert's contour integral) where all of n x n jittered shadow rays to the
//         emitter get through, 0 where none does, and in a penumbra the area-sampled
//         estimate over the same rays: (1/N) sum_k |J_k| cos(theta_x) cos(theta_k) V_k / (pi r_k^2)
//   I(x)  the light that arrives after one bounce or more: on a uniform mesh of about
//         `elements` elements, the system B'_i = rho_i (D_i + sum_j F_ij B'_j), with D_i
//         the direct light averaged over element i as above (at m x m points) and F_ij
//         from hemicubes, solved by Gauss-Seidel; then I_i = sum_j F_ij B'_j,
//         interpolated over the mesh's vertices (Gouraud).
// The direct light, which carries the sharp shadows and most of the error of a coarse
// solution, is exact at every pixel sample; only the smooth indirect part rests on a
// mesh. (Until a converged path-traced picture is the workbench's reference.)
struct ReferenceSettings {
  int elements = 3000;          // the uniform mesh of the indirect part
  int hemicube_resolution = 200;
  int shadow_rays_per_side = 6;  // n: n x n shadow rays from a point to each emitter
  int element_points_per_side = 3;  // m: the direct light of an element averaged at m x m points
  DisplaySettings display;       // size, eye rays per pixel, seed, threads (shading ignored)
};
void check(const ReferenceSettings& settings);  // throws std::invalid_argument

struct ReferencePicture {
  RadiosityPicture picture;
  std::vector<int> surface;  // per pixel, the surface its centre sees (-1: none): where the edges are
  int elements = 0;          // of the indirect part's mesh
  double indirect_share = 0; // of the picture's mean radiance (non-emitting pixels): how much rests on the mesh
};
ReferencePicture render_reference_picture(const RadiosityScene& scene, const ReferenceSettings& settings);

// Relative RMS difference of two pictures over blocks of block x block pixels away
// from edges:
//   sqrt(mean over blocks and channels of (t - r)^2 / r^2)
// each picture first averaged over the block (noise within a block cancels). A block
// counts only if every pixel of it and of the ring around it sees the same surface
// (`surface`, one id per pixel, as ReferencePicture's): a solution is scored on its
// surfaces, not on how its edges are sampled. Values below 1e-3 of the reference's
// mean are left out. Throws std::invalid_argument for pictures of different sizes, a
// block that does not divide them or ids of another size.
double relative_block_error(const Image& test, const Image& reference, int block, const std::vector<int>& surface);

}  // namespace gi
