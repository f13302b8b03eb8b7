#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh/polygon.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// A surface of a radiosity scene: a flat quadrilateral, ideally diffuse, with a
// reflectance rho (per colour channel) and an emitted radiosity E (light sources).
struct Surface {
  std::string name;
  std::array<vec3, 4> corners;  // counter-clockwise seen from the lit side
  Color reflectance;            // rho in [0, 1] for a physical surface
  Color emission{0.0};          // E, radiant exitance of a light (W/m^2 per channel)
};

struct RadiosityScene {
  std::string name;
  std::vector<Surface> surfaces;
  Camera camera;
};

// The lecture's two levels: the environment is broken into patches, the patches into
// elements. Light is shot from patches and received at elements (radiosity B is
// stored per element); a patch is the group of elements it was cut into.
struct Patch {
  Polygon shape;
  int surface;
  int first_element;  // its elements are elements[first_element, first_element + element_count)
  int element_count;
};

struct Element {
  Polygon shape;
  int surface;
  int patch;
  std::array<int, 4> vertices;  // into Mesh::vertices, in the order of shape.corners
};

struct Mesh {
  std::vector<Surface> surfaces;
  std::vector<Patch> patches;
  std::vector<Element> elements;
  // Element corners, shared by the elements of one surface that meet there (not across
  // surfaces: a vertex on the edge between the red wall and the floor belongs to each
  // twice, so vertex colours do not bleed around corners).
  std::vector<vec3> vertices;

  const Color& reflectance(const Element& e) const { return surfaces[e.surface].reflectance; }
  const Color& emission(const Element& e) const { return surfaces[e.surface].emission; }
};

struct MeshSettings {
  double patch_size = 1e30;   // the longest a patch's edge may be (scene units); huge: one patch per surface
  int elements_per_side = 1;  // each patch is cut into n x n elements
};

// Cuts every surface into ceil(edge / patch_size) patches along each edge pair
// (bilinearly, so the patches tile the quadrilateral exactly) and each patch into
// elements. Throws std::invalid_argument for bad settings, a bad surface (see
// make_polygon; reflectance or emission negative or not finite), two surfaces that
// overlap in one plane (overlaps.hpp; the message names both) or more than 10^6 elements.
Mesh make_mesh(const std::vector<Surface>& surfaces, const MeshSettings& settings);

// The elements' shapes, in order: what form factors are computed between.
std::vector<Polygon> element_shapes(const Mesh& mesh);

// The patch size that gives about `elements` elements with n x n elements per patch:
// side sqrt(area / elements). Each surface rounds its patches up, so the mesh may have
// a few percent more (the Cornell box: 20 707 for 20 000).
double patch_size_for(const std::vector<Surface>& surfaces, int elements, int elements_per_side);

// How many elements make_mesh would cut the surfaces into, by the same arithmetic,
// without making them: a count to check before any work.
double element_count(const std::vector<Surface>& surfaces, const MeshSettings& settings);

// patch_size_for, grown where its mesh would pass `most` elements to the smallest
// size whose mesh does not (bisection on element_count): a limit that is a lesson's
// documented maximum is then reached, never passed. Throws std::invalid_argument when
// even one patch per surface makes more than `most`.
double patch_size_at_most(const std::vector<Surface>& surfaces, int elements, int elements_per_side, int most);

}  // namespace gi
