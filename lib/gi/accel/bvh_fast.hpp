#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "gi/accel/bvh.hpp"
#include "gi/accel/bvh_collapse.hpp"

namespace gi {

// The production walk of a BVH, beside the lecture's (bvh_traverse.hpp, lab 5). It
// finds the same hits on the same tree, faster, by these changes (docs/05 measures each):
//
//   wide nodes    the binary tree collapsed into an 8-ary one (bvh_collapse.hpp): a node
//                 stands for up to seven of the binary tree's nodes, so a ray makes
//                 about half as many stops; by default the collapse of least SAH cost,
//                 which also chooses the leaves.
//   node layout   a node holds its eight children's boxes, axis by axis (256 bytes, four
//                 cache lines), and whether each child is a node or a leaf: a visit
//                 reads one node, not one per child.
//   float slabs   the slab tests four floats wide, two groups of four children (two
//                 independent chains of instructions, which the processor runs side by
//                 side), with the ray's origin and 1/d converted once per ray; widened
//                 (bvh_fast.cpp) so that it never misses a box the double test hits.
//   hit mask      the lanes' verdicts read in one instruction per group and the
//                 children taken bit by bit; a lone child entered goes on without the
//                 stack.
//   quads beside  the leaves' quads copied in the tree's order, so that a leaf's quads
//                 share cache lines.
//
// The primitives are still intersected in double by the same routines, so every hit
// is the very hit the plain walk finds, to the bit.
struct alignas(64) FastBvhNode {  // starts a cache line: a node is four whole ones
  // Child c's box along axis a is [bounds[2a][c], bounds[2a + 1][c]]: rows lo.x, hi.x,
  // lo.y, hi.y, lo.z, hi.z. An unused child has lo = +inf, hi = -inf: no ray enters it.
  float bounds[6][wide_width];
  // count[c] == 0: child c is the node nodes[index[c]] (or unused);
  // count[c] > 0:  child c is a leaf holding refs[index[c], index[c] + count[c]).
  std::int32_t index[wide_width];
  std::int32_t count[wide_width];
};
static_assert(sizeof(FastBvhNode) == 256, "four cache lines");

struct FastBvh {
  std::vector<FastBvhNode> nodes;  // nodes[0] is the root
  std::vector<PrimitiveRef> refs;  // the plain tree's refs, in the same order
  // refs[i]'s quad, copied, where refs[i] is a quad (elsewhere unused): a leaf's quads
  // side by side in memory, where scene.quads scatters them over the whole room.
  std::vector<Quad> quads;
  float reach = 0;                 // the largest |coordinate| of any box: sets the float test's margin
};

// Re-lays a built tree out for the fast walk, collapsed as settings.collapse says
// with leaves of at most settings.max_leaf_size primitives where the collapse makes
// them (linear in the tree's size).
FastBvh make_fast_bvh(const Bvh& bvh, const Scene& scene, const BvhSettings& settings = {});

// As closest_hit(const Bvh&, ...) and any_hit(const Bvh&, ...) of bvh_traverse.hpp,
// with no counts: the same hit or answer for every ray (a test holds them to it).
std::optional<Hit> closest_hit(const FastBvh& bvh, const Scene& scene, Ray& ray);
bool any_hit(const FastBvh& bvh, const Scene& scene, const Ray& ray);

}  // namespace gi
