#pragma once
#include "gi/image/image.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// How finely a mesh cuts the scene, as a picture: every element seen through the
// camera in the false colour of log4(A_largest / A_element), A_largest the largest
// surface's area -- how many times that surface would be quartered to make an element
// so small (on the largest surface, a quadtree leaf's level) -- with the elements'
// outlines drawn over it in black, and black where no element is seen. Two meshes of one
// scene drawn with the same `top` compare on one scale: an adaptive mesh's small leaves
// burn red where it cut finely, a uniform mesh is about one colour everywhere.
struct ElementSizes {
  Image image;
  double top = 0;  // the value shown red: the `top` given, or the mesh's largest when 0
};
ElementSizes render_element_sizes(const Mesh& mesh, const Camera& camera, int width, int height, double top,
                                  int threads);

}  // namespace gi
