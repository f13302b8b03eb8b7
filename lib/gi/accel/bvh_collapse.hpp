#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "gi/accel/bvh.hpp"

namespace gi {

// How the fast walk's 8-wide tree (bvh_fast.hpp) is made of a binary one: which of
// the binary tree's nodes become the children of each wide node, and which of those
// are leaves. Both rules below keep every primitive in exactly one leaf and every
// box the binary builder made; they differ in which boxes a ray meets.

inline constexpr int wide_width = 8;  // children per wide node

// One child of a wide node, as FastBvhNode will hold it: binary node `node`, whose box
// it keeps, made either a leaf holding refs[index, index + count) -- all of its
// subtree's primitives, which the binary tree keeps side by side -- or (count == 0)
// the wide node plan[index].
struct WideChild {
  std::int32_t node;
  std::int32_t index;
  std::int32_t count;
};
struct WideNode {
  std::array<WideChild, wide_width> child;
  int size = 0;
};
// The wide tree without its boxes, depth first: plan[0] is the root, which stands for
// the binary root. Empty when the binary tree is empty or a single leaf.
using WidePlan = std::vector<WideNode>;

// The cost model the SAH collapse minimises, in units of one visit to a wide node: a
// ray that reaches a wide node, with probability A_node / A_root, tests its eight
// boxes (C_wide); one that reaches a leaf tests its N primitives (N C_prim). A quad
// test runs more instructions than a test of four boxes (about 140 against 50, counted
// by callgrind on the four-wide walk, docs/05) but takes less time: the visits wait on
// each other, one node's test choosing the next node, while a leaf's quads are tested
// side by side, and fewer, larger leaves make a smaller tree that stays in cache. Timed on quad_room's camera and random rays at 10 000 and
// 100 000 quads with C_prim from 0.2 to 1: 0.3 was among the fastest at 10 000 and
// clearly fastest at 100 000 (random nearest hits 0.86 of Embree's speed against 0.72
// at 0.5; docs/05).
inline constexpr double wide_node_cost = 1.0;
inline constexpr double wide_primitive_cost = 0.3;

// The expected cost per ray of the wide tree a plan makes, by the model above.
double sah_cost(const Bvh& bvh, const WidePlan& plan);

// The binary tree's own leaves; a node's children are its binary children and, while
// fewer than eight, the interior child with the largest box replaced by its two (a ray
// is likelier to enter a large box, so opening it spares the most stops). Greedy: it
// looks one level ahead.
WidePlan collapse_largest_first(const Bvh& bvh);

// The plan of least SAH cost among all that use the binary tree's boxes (Ylitie,
// Karras and Laine, "Efficient incoherent ray traversal on GPUs through compressed
// wide BVHs", HPG 2017), with leaves of at most max_leaf_size primitives where a
// leaf is cheaper than the subtree it replaces. Best made from a binary tree built
// down to one primitive a leaf, so that the collapse chooses the leaves. Linear in
// the tree's size.
WidePlan collapse_sah(const Bvh& bvh, int max_leaf_size);

}  // namespace gi
