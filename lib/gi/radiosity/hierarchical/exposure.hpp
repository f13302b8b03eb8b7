#pragma once
#include <cstdint>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// Part of a surface can lie inside a closed solid: the Cornell box's floor under its
// two blocks (18% of the floor), a wall behind a cupboard pushed against it. No light
// reaches such a part and none leaves it, yet a quadtree node that straddles a block's
// foot holds some of it. Left in, it costs light twice over: a link from the node
// hands on the mean B of all of it, dark part included, after its shadow rays have
// already found that part hidden (the receivers of a coarse floor node came out 2-3%
// dark); and light gathered by the node is shared over all of it, so its open part
// gets only its share (docs/13, "Buried parts").
//
// A point is buried when it sees only the inside of a solid: each of five directions
// of its hemisphere (the normal, and four at 60 degrees from it) meets a surface from
// behind. One direction is not enough: under a single-sided panel a point sees the
// panel's back straight up, and the room past its edges.
bool buried(const FormFactorScene& blockers, const vec3& point, const vec3& normal, double scene_size);

// A node's open part, judged at the centres of a 4 x 4 grid of cells over its
// parameter square: bit 4 v + u of Node::open is set when cell (u, v) is open.
inline constexpr int exposure_cells = 4;
std::uint16_t open_cells(const FormFactorScene& blockers, const Hierarchy& hierarchy, int node);
bool open_at(const Node& node, double u, double v);  // is the cell holding the node's point (u, v) open?

// Judges the cells of nodes [first, end) (new ones: splits append), in parallel, then
// sets every node's open area: a leaf's area times its share of open cells, above
// that the sum of its children's, so that push-pull's means over open areas keep the
// power (push_pull.hpp).
void measure_exposure(Hierarchy& hierarchy, const FormFactorScene& blockers, int first, int threads);

}  // namespace gi
