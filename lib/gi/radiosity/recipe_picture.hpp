#pragma once
#include "gi/image/image.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/radiosity/recipe.hpp"

namespace gi {

// A solved recipe's picture through a camera, the way lesson 12 scores it against the
// path-traced truth: either B read from the mesh (render_radiosity_picture), or -- with
// direct_per_pixel -- the direct light drawn exactly at every eye ray's hit and only
// what bounced more than once read from the mesh (direct_display.hpp). The second needs
// a recipe solved with exact_direct, and its light cells are `direct`'s.
// Throws std::invalid_argument for direct_per_pixel without the recipe's direct part,
// and as render_radiosity does.
Image recipe_picture(const RecipeResult& result, const Camera& camera, const DisplaySettings& display,
                     bool direct_per_pixel, const DirectLightSettings& direct);

}  // namespace gi
