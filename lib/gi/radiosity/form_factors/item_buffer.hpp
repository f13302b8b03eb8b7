#pragma once
#include <array>
#include <vector>

#include "gi/radiosity/form_factors/hemicube.hpp"
#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

// What a hemicube sees: for every cell of its five faces, the index of the nearest
// polygon there, or -1 where it sees nothing or the back of a polygon (surfaces are
// one-sided: a back face hides what is behind it but receives nothing). Rendered
// like a frame of a z-buffer renderer, one per face: occlusion comes for free.
struct ItemBuffer {
  int resolution = 0;
  std::array<std::vector<int>, hemicube_faces> items;      // top: res x res; sides: res/2 rows of res
  std::array<std::vector<double>, hemicube_faces> depths;  // distance along the face's axis (scratch)
  // Per polygon: how many cells its image on the five faces covers (fractional, before
  // occlusion), for the polygons that face the hemicube; 0 for the others. An image
  // smaller than one cell is counted whole or not at all: the form factor is aliased.
  std::vector<double> footprint;

  int rows(HemicubeFace face) const { return face == HemicubeFace::Top ? resolution : resolution / 2; }
};

// Renders `polygons` into the hemicube standing at `centre` with unit normal `normal`
// (its x and y axes are any tangents; the delta form factors do not care). Polygons
// behind the base plane, or in it within 1e-9 of their distance (the patch itself and
// its coplanar neighbours), are left out: stand the hemicube on lifted_centre, so
// that a twisted patch and its elements lie below it. Reuses `buffer`'s memory
// between calls. Throws std::invalid_argument for an invalid polygon (check), a
// resolution that is not even in [2, 2000], or a centre or normal that is not finite
// and unit.
void render_item_buffer(const std::vector<Polygon>& polygons, const vec3& centre, const vec3& normal, int resolution,
                        ItemBuffer& buffer);

// The same without checking the polygons, for callers that checked them once for many
// hemicubes (a FormFactorScene, a matrix): checking is as slow as rendering small ones.
void render_checked_item_buffer(const std::vector<Polygon>& polygons, const vec3& centre, const vec3& normal,
                                int resolution, ItemBuffer& buffer);

}  // namespace gi
