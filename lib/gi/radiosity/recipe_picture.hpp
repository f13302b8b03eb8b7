#pragma once
#include <cstdint>

#include "gi/image/image.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/recipe.hpp"

namespace gi {

// A solved recipe's picture through a camera, the way lessons 12 and 15 score it against
// the path-traced truth: either the mesh's radiance function (MeshRadiance of B), or --
// with direct_per_pixel -- the sum of two: the direct light exactly at every eye ray's
// hit (DirectRadiance) and only what bounced more than once read from the mesh
// (direct_display.hpp). The second needs a recipe solved with exact_direct, and its
// light cells are `direct`'s. Pixel i draws from stream i of `seed`, on `threads`
// threads. Throws std::invalid_argument for direct_per_pixel without the recipe's
// direct part, and as render_radiosity_picture does.
Image recipe_picture(const RecipeResult& result, const Camera& camera, const DisplaySettings& display,
                     bool direct_per_pixel, const DirectLightSettings& direct, std::uint64_t seed, int threads);

}  // namespace gi
