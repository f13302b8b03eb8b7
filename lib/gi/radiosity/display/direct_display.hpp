#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/form_factors/direct_light.hpp"
#include "gi/radiosity/display/display.hpp"

namespace gi {

// The direct light drawn per pixel instead of read from the mesh -- the two-pass idea
// (Chen, Rushmeier, Miller and Turner 1991): a mesh is good at the smooth light that
// has bounced, and bad at shadows, whose edges cross its elements. So the picture is
// split:
//   L(x) = [E(x) + rho(x) H(x)] / pi  +  B_indirect(x) / pi
// with H(x) exact at every eye ray's hit (DirectLighting), and B_indirect = B - E - D
// (indirect_part) shown from the mesh as usual (render_radiosity_picture). Both
// pictures cast the same eye rays (same settings and seed), so their sum is the
// picture of the sum.

// B - E - D for every element: what has bounced more than once.
std::vector<Color> indirect_part(const Mesh& mesh, const std::vector<Color>& B, const std::vector<Color>& D);

// (E + rho H(x)) / pi through every pixel, with the display's eye rays. `scene` must be
// built from element_shapes(mesh). Throws std::invalid_argument as render_radiosity does.
Image render_direct_light(const FormFactorScene& scene, const Mesh& mesh, const Camera& camera,
                          const DisplaySettings& settings, const DirectLightSettings& direct);

// The whole split picture: render_direct_light plus the mesh's B - E - D drawn by
// render_radiosity_picture. `D` is the mesh's direct radiosity (direct_radiosity), the
// part the per-pixel term replaces.
Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const Camera& camera, const DisplaySettings& settings,
                           const DirectLightSettings& direct);
// The same with B - E - D given at the vertices too, one per mesh vertex, for Smooth
// shading to interpolate (hierarchical radiosity's final gather, link_gather.hpp).
Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const std::vector<Color>& vertex_indirect,
                           const Camera& camera, const DisplaySettings& settings, const DirectLightSettings& direct);

}  // namespace gi
