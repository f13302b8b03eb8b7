#pragma once
#include <cstdint>
#include <vector>

#include "gi/geometry/aabb.hpp"
#include "gi/scene/scene.hpp"

namespace gi {

// A bounding volume hierarchy over a scene's spheres and quads: a binary tree of
// boxes, each holding its children's boxes, with the primitives in the leaves. A ray
// that misses a box skips everything inside it. Planes are unbounded: they stay out
// of the tree and are tested one by one (see world.hpp).

// Where the builder cuts a node's primitives in two.
//   Sah     the surface area heuristic: the cut with the least expected cost
//           C_trav + (A_left N_left + A_right N_right) / A_node * C_isect, since a
//           random ray that hits the node hits a child with probability A_child / A_node.
//           Only the borders of `bins` equal slices of the centroids' extent are tried.
//   Median  half the primitives on each side, along the centroids' longest axis: the
//           simple rule, for comparison.
enum class Split { Sah, Median };

// How the production walk (bvh_fast.hpp) makes the binary tree 8-wide (bvh_collapse.hpp).
//   Sah           the wide tree of least SAH cost made of the binary tree's boxes; it
//                 chooses the leaves too, so make_world builds the binary tree down
//                 to one primitive a leaf for it
//   LargestFirst  the binary tree's own leaves; the largest interior child opened first
enum class WideCollapse { Sah, LargestFirst };

struct BvhSettings {
  int max_leaf_size = 4;  // 1..255; a node with more primitives is always split
  int bins = 12;          // 2..256, for Split::Sah
  Split split = Split::Sah;
  WideCollapse collapse = WideCollapse::Sah;  // for the fast walk only (make_world, make_fast_bvh)
};

// A primitive in the tree: which of the scene's vectors, and where in it. Indices
// rather than pointers, so a World can be copied or moved with its scene.
enum class PrimitiveKind : std::int32_t { Sphere, Quad, Triangle };
struct PrimitiveRef {
  PrimitiveKind kind;
  std::int32_t index;
};

// One node of the flattened tree. Nodes are stored depth first, so an interior
// node's left child is the next node in the array and only the right child needs
// an index. A leaf holds refs[offset, offset + count).
//
// The box is stored in float, rounded outwards, and turned back into double (an
// exact conversion) for the slab test. Rays and the test stay in double like the
// rest of the geometry, and the box can only be a hair too large, never too small;
// but the node is 32 bytes instead of 56: two fit in a cache line, and a large
// scene's tree takes half the cache. A ray through 100 000 quads spends much of its
// time waiting for nodes to arrive from memory.
struct BvhNode {
  glm::vec3 lo, hi;         // float
  std::int32_t offset = 0;  // interior node: index of the right child; leaf: index of its first ref
  std::int32_t count = 0;   // leaf: number of refs; 0 marks an interior node
};

// The node's box in double precision, for the slab test.
inline Aabb box(const BvhNode& node) { return {vec3(node.lo), vec3(node.hi)}; }

struct Bvh {
  std::vector<BvhNode> nodes;      // nodes[0] is the root; empty for a scene without spheres and quads
  std::vector<PrimitiveRef> refs;  // the leaves' primitives, leaf after leaf
};

// The traversal keeps the nodes still to visit on a fixed stack of this size (no
// allocation per ray); the builder never makes a tree deeper than it can hold.
inline constexpr int bvh_stack_size = 64;

// Builds the tree over scene.spheres and scene.quads. Deterministic: the same scene
// and settings give the same tree. Throws std::invalid_argument for settings out of
// range or more than 2^31 - 1 primitives.
Bvh build_bvh(const Scene& scene, const BvhSettings& settings = {});

// The shape of a built tree, for the lesson's tables. sah_cost is the tree's
// expected cost per ray, in units of one primitive test, by the same model the
// builder minimises: comparing it tells how much better one tree is than another.
struct BvhStats {
  int nodes = 0;
  int leaves = 0;
  int depth = 0;  // edges from the root to the deepest leaf
  int largest_leaf = 0;
  double sah_cost = 0;
};
BvhStats bvh_stats(const Bvh& bvh);

}  // namespace gi
