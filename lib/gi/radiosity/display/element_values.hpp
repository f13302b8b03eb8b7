#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// One number per element of a mesh, painted on the mesh as the camera sees it: each
// element in the false colour of its value (false_colour: lo black ... hi red; with
// `log10`, of the values' logarithms, and lo black for 0 too), the elements' outlines
// drawn over it in black, black where no element is seen. `highlight`, when not -1,
// is the element drawn white: the one the values are about (one row of a form-factor
// matrix: the light leaving it and where it lands).
Image render_element_values(const Mesh& mesh, const std::vector<double>& values, const Camera& camera, int width,
                            int height, double lo, double hi, bool log10, int threads, int highlight = -1);

// How finely a mesh cuts the scene: each element's value is log4(A_largest / A_element),
// A_largest the largest surface's area -- how many times that surface would be quartered
// to make an element so small (on the largest surface, a quadtree leaf's level). Two
// meshes of one scene drawn with the same `top` compare on one scale: an adaptive mesh's
// small leaves burn red where it cut finely, a uniform mesh is about one colour
// everywhere.
struct ElementSizes {
  Image image;
  double top = 0;  // the value shown red: the `top` given, or the mesh's largest when 0
};
ElementSizes render_element_sizes(const Mesh& mesh, const Camera& camera, int width, int height, double top,
                                  int threads);

}  // namespace gi
