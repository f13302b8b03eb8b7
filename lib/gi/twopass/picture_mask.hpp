#pragma once
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/twopass/two_pass_scene.hpp"

namespace gi {

// The blocks of a two-pass picture scored against the reference: surface_mask.hpp's
// interior blocks of the diffuse surfaces (one surface, not the light, no edge), less
// every block that an eye ray through one of its pixels or the ring around it sends
// into a sphere. So the score is over diffuse surfaces seen directly, where all the
// methods can agree; what the spheres show is scored by the whole picture.
BlockMask diffuse_interior_blocks(const TwoPassScene& scene, int width, int height, int block);

}  // namespace gi
