#pragma once
#include <functional>

#include "gi/image/image.hpp"
#include "gi/radiosity/form_factors/hemicube.hpp"

namespace gi {

// A hemicube unfolded flat, as if cut along its four vertical edges: the top face in
// the middle of a 2 res x 2 res image (+x to the right, +y up), each half side face
// folded out beside the top edge it shares, its horizon row outermost. The corners
// stay black. `colour(face, column, row)` gives each cell's colour, with columns and
// rows as in project_to_hemicube.
Image unfold_hemicube(int resolution, const std::function<Pixel(HemicubeFace, int column, int row)>& colour);

}  // namespace gi
