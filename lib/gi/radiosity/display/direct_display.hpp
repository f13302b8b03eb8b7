#pragma once
#include <cstdint>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/form_factors/direct_light.hpp"

namespace gi {

// The direct light drawn per pixel instead of read from the mesh -- the two-pass idea
// (Chen, Rushmeier, Miller and Turner 1991): a mesh is good at the smooth light that
// has bounced, and bad at shadows, whose edges cross its elements. So the radiance is
// split, and each part is a radiance function of its own (render_pass.hpp):
//   L(x) = [E(x) + rho(x) H(x)] / pi  +  B_indirect(x) / pi
//          DirectRadiance                MeshRadiance of B - E - D
// with H(x) exact at every eye ray's hit (DirectLighting), and B_indirect = B - E - D
// (indirect_part) read off the mesh as usual. Their sum is one radiance function: each
// eye ray gets both parts.

// B - E - D for every element: what has bounced more than once.
std::vector<Color> indirect_part(const Mesh& mesh, const std::vector<Color>& B, const std::vector<Color>& D);

// (E + rho H(x)) / pi at the point an eye ray hits. `scene` must be built from
// element_shapes(mesh) (it casts the shadow rays too); `lights` are the mesh's. It draws
// no random numbers. Backs of surfaces and the void show black.
struct DirectRadiance {
  const FormFactorScene& scene;
  const Mesh& mesh;
  const DirectLighting& lights;
  Color operator()(const Ray& ray, PixelSample& sample) const;
};

// The whole split picture through the display's eye rays: DirectRadiance plus the
// mesh's B - E - D. `D` is the mesh's direct radiosity (direct_radiosity), the part the
// per-pixel term replaces; `vertex_indirect`, when given, is B - E - D at the mesh's
// vertices for Smooth shading to interpolate (hierarchical radiosity's final gather,
// link_gather.hpp), else vertex_radiosity of it. Throws std::invalid_argument as
// render_radiosity_picture does.
Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const Camera& camera, const DisplaySettings& settings,
                           const DirectLightSettings& direct, std::uint64_t seed, int threads);
Image render_split_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                           const std::vector<Color>& D, const std::vector<Color>& vertex_indirect,
                           const Camera& camera, const DisplaySettings& settings, const DirectLightSettings& direct,
                           std::uint64_t seed, int threads);

}  // namespace gi
