#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// The mesh drawn over a picture: one eye ray through each pixel's centre finds the
// polygon it sees (-1: nothing, or a back face), and a line is drawn wherever two
// neighbouring pixels see different polygons. Leaves smaller than a pixel come out
// as a dark patch: there the mesh is finer than the picture.
std::vector<int> visible_polygons(const FormFactorScene& scene, const Camera& camera, int width, int height,
                                  int threads);

// `picture` with `line` mixed in, `opacity` in [0, 1], on the pixels where the
// polygon seen changes to the right or below. `ids` from visible_polygons, same size.
Image draw_mesh_lines(const Image& picture, const std::vector<int>& ids, const Color& line, double opacity);

}  // namespace gi
