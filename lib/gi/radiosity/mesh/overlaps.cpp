#include "gi/radiosity/mesh/overlaps.hpp"

#include <cmath>

#include "gi/radiosity/mesh/convex_polygon.hpp"

namespace gi {

namespace {

double size_of(const Polygon& p) { return std::max(length(p.corners[2] - p.corners[0]), length(p.corners[3] - p.corners[1])); }

bool within_plane(const Polygon& p, const Polygon& plane, double tolerance) {
  for (const vec3& c : p.corners)
    if (std::abs(dot(c - plane.centre, plane.normal)) > tolerance) return false;
  return true;
}

bool boxes_meet(const Aabb& a, const Aabb& b) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.hi[axis] < b.lo[axis] || b.hi[axis] < a.lo[axis]) return false;
  return true;
}

}  // namespace

double shared_area(const Polygon& a, const Polygon& b) {
  const double tolerance = 1e-12 * std::max(size_of(a), size_of(b));
  if (!within_plane(a, b, tolerance) || !within_plane(b, a, tolerance)) return 0;
  return overlap_area(outline(a), outline(b));
}

bool overlapping(const Polygon& a, const Polygon& b) { return shared_area(a, b) > 1e-6 * std::min(a.area, b.area); }

std::optional<std::pair<int, int>> find_overlap(const std::vector<Polygon>& polygons, const Bvh& bvh) {
  if (bvh.nodes.empty()) return std::nullopt;
  std::vector<int> stack;
  for (int i = 0; i < static_cast<int>(polygons.size()); ++i) {
    // The polygon's box, grown by the coplanarity tolerance (a flat box has no depth).
    Aabb box;
    for (const vec3& c : polygons[i].corners) grow(box, c);
    const vec3 margin(1e-12 * size_of(polygons[i]));
    box.lo -= margin, box.hi += margin;
    stack.assign(1, 0);
    while (!stack.empty()) {  // every leaf whose box meets this one
      const int index = stack.back();
      stack.pop_back();
      const BvhNode& node = bvh.nodes[index];
      if (!boxes_meet(box, gi::box(node))) continue;
      if (node.count == 0) {
        stack.push_back(index + 1);   // left child: the next node (depth-first order)
        stack.push_back(node.offset);  // right child
        continue;
      }
      for (int r = node.offset; r < node.offset + node.count; ++r) {
        const int j = bvh.refs[r].index / 2;
        if (j > i && overlapping(polygons[i], polygons[j])) return std::pair{i, j};
      }
    }
  }
  return std::nullopt;
}

}  // namespace gi
