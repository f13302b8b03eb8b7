#pragma once
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/geometry/aabb.hpp"
#include "gi/scene/scene.hpp"

namespace gi {

// The rays ray-query benchmarks cast, shared by lesson 05 and the Embree comparison
// so that both time the very same rays.

// One eye ray through the centre of every `stride`-th pixel of a width x height
// image of the scene's camera: coherent rays, neighbours taking the same path
// through the tree.
std::vector<Ray> camera_rays(const Scene& scene, int width, int height, int stride = 1);

// `count` rays from uniformly random points of `region` in uniformly random
// directions: no coherence at all, like the bounces of a path tracer.
std::vector<Ray> random_rays(const Aabb& region, int count, Rng& rng);

}  // namespace gi
