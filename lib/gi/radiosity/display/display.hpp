#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/render/render_pass.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// Radiosity is view-independent: once B is known, any camera can look at it. As a
// radiance function (render_pass.hpp) a solution is the radiance L = B / pi of the point
// an eye ray hits on the elements:
//   Flat    the element's own B: every element a tile of one colour
//   Smooth  Gouraud's: B interpolated bilinearly from the element's four vertex
//           colours (vertex_radiosity), so the tiles blend
// Backs of surfaces and the void show black. It draws no random numbers.
enum class Shading { Flat, Smooth };

struct MeshRadiance {
  const FormFactorScene& scene;    // built from element_shapes(mesh): what eye rays hit
  const Mesh& mesh;
  const std::vector<Color>& B;         // per element
  const std::vector<Color>& vertex_B;  // per vertex, for Smooth
  Shading shading = Shading::Smooth;
  Color operator()(const Ray& ray, PixelSample& sample) const;
};

// Throws std::invalid_argument unless there is one B per element, a scene of the
// mesh's elements and (Smooth) one vertex_B per vertex.
void check(const MeshRadiance& radiance);

// A picture of a solution: n x n jittered eye rays per pixel, box-filtered.
// The image holds radiance; write it with an exposure (write_png) to taste.
struct DisplaySettings {
  int width = 320;
  int height = 320;
  int samples = 2;  // n x n jittered eye rays per pixel, box-filtered (1..16)
  Shading shading = Shading::Smooth;
  // > 0: the picture to show averages each eye ray's radiance clamped to this. A light
  // 20x brighter than what the picture shows as white otherwise turns every pixel one
  // of its samples touches white, and its edges look ragged. Set it to the radiance
  // the picture will show as white (1 / exposure).
  double white = 0;
  Sampling sampling() const { return {Sampler::Jittered, samples}; }
};

// `radiance` the plain mean of the eye rays (linear, for a PFM that another renderer can
// be compared with) and `shown` the mean of the same rays clamped to settings.white (the
// same as radiance when white is 0).
struct RadiosityPicture {
  Image radiance, shown;
};

// The mesh's solution B (one per element) through `camera`; pixel i's eye rays draw from
// stream i of `seed`, on `threads` threads (0 = all cores): the same picture for any
// count. `scene` must be built from element_shapes(mesh). Smooth shading interpolates
// vertex_radiosity(mesh, B), or the vertex radiosities given, one per mesh vertex (for
// meshes whose vertices need more than the mean: hierarchical radiosity's leaves, with
// their T-vertices, leaf_mesh.hpp).
RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const Camera& camera, const DisplaySettings& settings, std::uint64_t seed,
                                          int threads);
RadiosityPicture render_radiosity_picture(const FormFactorScene& scene, const Mesh& mesh, const std::vector<Color>& B,
                                          const std::vector<Color>& vertex_B, const Camera& camera,
                                          const DisplaySettings& settings, std::uint64_t seed, int threads);

// Any radiance function's picture by the display's eye rays: the film's mean, and the
// mean of the same rays clamped to settings.white.
RadiosityPicture render_display(RadianceFunction radiance, const Camera& camera, const DisplaySettings& settings,
                                std::uint64_t seed, int threads);

// Several solutions of one mesh in a grid, `columns` to a row, read row by row, with a
// white gap between: a solver's iterates side by side (lessons 09 and 10). Each picture
// is `size` x `size` pixels of 2 x 2 jittered eye rays, smooth shading, shown as the
// display shows it with white at radiance 1; every one draws from the same streams of
// `seed`.
Image solutions_grid(const Mesh& mesh, const std::vector<std::vector<Color>>& solutions, int columns,
                     const Camera& camera, int size, std::uint64_t seed, int threads);

// "2 x 2 jittered eye rays, box filter": how the display samples each pixel.
std::string describe_pixel_samples(const DisplaySettings& settings);

}  // namespace gi
