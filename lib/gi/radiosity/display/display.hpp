#pragma once
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// Radiosity is view-independent: once B is known, any camera can look at it. A
// picture is made by casting one eye ray per pixel (jittered over the pixel, a few
// per pixel) into the elements and showing the radiance L = B / pi of the point hit:
//   Flat    the element's own B: every element a tile of one colour
//   Smooth  Gouraud's: B interpolated bilinearly from the element's four vertex
//           colours (vertex_radiosity), so the tiles blend
// The image holds radiance; write it with an exposure (write_png) to taste.
enum class Shading { Flat, Smooth };

struct DisplaySettings {
  int width = 320;
  int height = 320;
  int samples = 2;  // n x n jittered eye rays per pixel, box-filtered
  Shading shading = Shading::Smooth;
  // > 0: each eye ray's radiance is clamped to this before the pixel's samples are
  // averaged. A light 20x brighter than what the picture shows as white otherwise
  // turns every pixel one of its samples touches white, and its edges look ragged.
  // Set it to the radiance the picture will show as white (1 / exposure).
  double white = 0;
  int threads = 0;
  std::uint64_t seed = 1;
};

// `scene` must be built from element_shapes(mesh); B holds one radiosity per element.
// Backs of surfaces and the void show black. Same image for any thread count.
// Returns the picture to show: with each eye ray clamped to settings.white.
Image render_radiosity(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                       const Camera& camera, const DisplaySettings& settings);

// The same eye rays, averaged twice: `radiance` the plain mean (linear, for a PFM
// that another renderer can be compared with) and `shown` with each ray clamped to
// settings.white first (the same as radiance when white is 0).
struct RadiosityPicture {
  Image radiance, shown;
};
RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const Camera& camera, const DisplaySettings& settings);
// The same with the vertex radiosities given, one per mesh vertex (Smooth shading
// interpolates them), for meshes whose vertices need more than vertex_radiosity's
// mean: the leaves of hierarchical radiosity, with their T-vertices (leaf_mesh.hpp).
RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const std::vector<Color>& vertex_B, const Camera& camera,
                                          const DisplaySettings& settings);

// "2 x 2 jittered eye rays, box filter": how the display samples each pixel.
std::string describe_pixel_samples(const DisplaySettings& settings);

}  // namespace gi
