#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "gi/accel/bvh.hpp"
#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

// Two polygons that lie in one plane (every corner of each within 1e-12 of the larger
// one's size from the other's plane, facing the same way or back to back) and share
// area: the area they share. 0 for any other pair, polygons meeting along an edge
// included. Coincident polygons make every method ambiguous -- which of them does a
// ray hit, which wins a z-buffer tie? -- so scenes refuse them. Polygons farther apart
// are taken, and every method gives finite form factors for them, but gaps this small
// are below what the methods resolve: Monte Carlo's rays start 1e-7 of the sender's
// size above it, and the hemicube leaves out what lies within 1e-9 of its base.
double shared_area(const Polygon& a, const Polygon& b);

// True when shared_area is more than 1e-6 of the smaller polygon's area.
bool overlapping(const Polygon& a, const Polygon& b);

// The first overlapping pair (i < j) among `polygons`, or nothing. Candidates come
// from `bvh`, a tree over the polygons' triangles, polygon k being triangles 2k and
// 2k + 1 (as FormFactorScene builds it): only polygons whose boxes meet are compared.
std::optional<std::pair<int, int>> find_overlap(const std::vector<Polygon>& polygons, const Bvh& bvh);

}  // namespace gi
