#include "gi/radiosity/recipe_picture.hpp"

#include <stdexcept>

#include "gi/radiosity/display/direct_display.hpp"
#include "gi/radiosity/hierarchical/link_gather.hpp"

namespace gi {

Image recipe_picture(const RecipeResult& result, const Camera& camera, const DisplaySettings& display,
                     bool direct_per_pixel, const DirectLightSettings& direct, std::uint64_t seed, int threads) {
  const FormFactorScene elements(element_shapes(result.mesh));
  if (!direct_per_pixel)
    return render_radiosity_picture(elements, result.mesh, result.B, camera, display, seed, threads).radiance;
  if (result.direct.size() != result.B.size())
    throw std::invalid_argument("recipe picture: the direct light per pixel needs a recipe solved with exact_direct");
  // L = (E + rho H(x)) / pi per eye ray, plus (B - E - D) / pi from the mesh; for
  // hierarchical radiosity gathered over the links at the leaves' corners (link_gather.hpp).
  if (!result.hierarchy)
    return render_split_picture(elements, result.mesh, result.B, result.direct, camera, display, direct, seed, threads);
  return render_split_picture(elements, result.mesh, result.B, result.direct,
                              gathered_at_vertices(*result.hierarchy, leaf_mesh(*result.hierarchy), threads), camera,
                              display, direct, seed, threads);
}

}  // namespace gi
