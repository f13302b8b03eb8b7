#pragma once
#include <vector>

#include "gi/geometry/aabb.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"

namespace gi {

// Shaft culling (Haines and Wallace 1994), in a simple form. The shadow rays between
// two patches are segments between points of the two, so they lie in the box around
// the patches' corners, and on the far side of a plane only if a corner is:
//   a triangle can stop one only if its box meets the box around the ends, and
//   its plane has ends on both sides.
// A Shaft gathers those few triangles once (the boxes from the scene's BVH), and its
// visible() tests a segment against them alone: the same ray, the same triangle test,
// so the same answer as FormFactorScene::visible for every segment between the ends --
// at the cost of a loop over a handful of triangles (mostly none, between two walls of
// a room) instead of a walk down the tree per ray.
class Shaft {
 public:
  // Every segment asked about must start and end inside the convex hull of `ends`
  // (the points themselves, or the corners of the patches they lie on).
  Shaft(const FormFactorScene& scene, const std::vector<vec3>& ends);

  bool visible(const vec3& from, const vec3& to) const;
  int candidates() const { return static_cast<int>(triangles_.size()); }

 private:
  const FormFactorScene* scene_;
  std::vector<int> triangles_;  // indices into scene.world().scene.triangles
};

}  // namespace gi
