#pragma once
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/render/picture_error.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// The blocks of a radiosity scene's picture where a method can be scored against the
// truth (picture_error.hpp): those whose pixels and ring all see one surface through
// their centres, that surface not a light. So the light, whose radiance is given, not
// computed, and 20x the rest, is left out with every edge, corner and silhouette.
// Throws std::invalid_argument unless block divides width and height.
BlockMask interior_blocks(const std::vector<Surface>& surfaces, const Camera& camera, int width, int height,
                          int block);

}  // namespace gi
