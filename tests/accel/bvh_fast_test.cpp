// The production walk (bvh_fast.hpp) against the lecture's (bvh_traverse.hpp) on the
// same tree: the same hit to the bit for every ray, and the same any-hit answer. The
// rays include the ones a float slab test is most likely to lose: along the axes
// (1/d infinite), inside the flat boxes of the room's walls, and grazing their edges.
#include "gi/accel/bvh_fast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gi/accel/bvh_traverse.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/sampling.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/camera.hpp"

using gi::Ray;
using gi::vec3;

namespace {

// Random rays in the box [lo, hi]; every other one is snapped to an axis or to a
// plane (a direction component of exactly +0 or -0), some start on a wall's plane.
std::vector<Ray> hard_rays(const vec3& lo, const vec3& hi, int count, std::uint64_t seed) {
  gi::Rng rng(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const vec3 origin = lo + (hi - lo) * vec3(rng.uniform(), rng.uniform(), rng.uniform());
    Ray ray{origin, gi::sample_uniform_sphere({rng.uniform(), rng.uniform()})};
    const int axis = i % 3;
    if (i % 2 == 1) ray.direction[axis] = (i % 4 == 1) ? 0.0 : -0.0;  // inside a slab's planes
    if (i % 8 == 3) ray.direction[(axis + 1) % 3] = 0.0;              // along an axis
    if (i % 5 == 4) ray.origin[axis] = rng.uniform() < 0.5 ? lo[axis] : hi[axis];  // on a face
    if (i % 7 == 2) ray.t_max = 2 * rng.uniform();
    ray.direction = gi::normalize(ray.direction);
    rays.push_back(ray);
  }
  return rays;
}

// Every ray: the plain and the fast walk return the same hit, bit for bit. At least
// `min_hits` rays hit something, so that the comparison is not of misses only.
// `settings` build the binary tree, `wide` make it 8-wide.
void expect_same_hits(const gi::Scene& scene, const std::vector<Ray>& rays, int min_hits,
                      const gi::BvhSettings& settings = {}, const gi::BvhSettings& wide = {}) {
  const gi::Bvh bvh = gi::build_bvh(scene, settings);
  const gi::FastBvh fast = gi::make_fast_bvh(bvh, scene, wide);
  gi::TraversalCounts counts;
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray a = rays[i], b = rays[i];
    const auto plain_hit = gi::closest_hit(bvh, scene, a, counts);
    const auto fast_hit = gi::closest_hit(fast, scene, b);
    ASSERT_EQ(fast_hit.has_value(), plain_hit.has_value()) << "ray " << i << ": the fast walk lost or made a hit";
    EXPECT_EQ(gi::any_hit(fast, scene, rays[i]), gi::any_hit(bvh, scene, rays[i], counts)) << "ray " << i;
    if (!plain_hit) continue;
    ++hits;
    EXPECT_EQ(fast_hit->t, plain_hit->t) << "ray " << i;
    EXPECT_EQ(fast_hit->object, plain_hit->object) << "ray " << i;
    EXPECT_EQ(fast_hit->point, plain_hit->point) << "ray " << i;
    EXPECT_EQ(b.t_max, a.t_max) << "ray " << i << ": both leave t_max at the hit";
    // The ray cut exactly at its hit, as a shadow ray to a point on that surface: both
    // walks keep it (the box crossing, by other arithmetic than the quad's, can round
    // to just past t_max: the lab walk's box_reach and the float walk's padded boxes
    // must let that box in).
    Ray cut = rays[i], cut_plain = rays[i];
    cut.t_max = cut_plain.t_max = plain_hit->t;
    const auto cut_hit = gi::closest_hit(fast, scene, cut);
    const auto cut_plain_hit = gi::closest_hit(bvh, scene, cut_plain, counts);
    ASSERT_TRUE(cut_hit) << "ray " << i << " cut at its hit lost it";
    ASSERT_TRUE(cut_plain_hit) << "ray " << i << " cut at its hit lost it in the lab walk";
    EXPECT_EQ(cut_hit->t, plain_hit->t) << "ray " << i;
    EXPECT_EQ(cut_plain_hit->t, plain_hit->t) << "ray " << i;
    EXPECT_EQ(cut_hit->object, cut_plain_hit->object) << "ray " << i;
    EXPECT_TRUE(gi::any_hit(fast, scene, cut)) << "ray " << i;
    EXPECT_TRUE(gi::any_hit(bvh, scene, cut, counts)) << "ray " << i;
  }
  EXPECT_GE(hits, min_hits) << "the rays should hit things";
}

}  // namespace

TEST(FastBvh, AWideNodeStandsForUpToSevenBinaryOnes) {
  const gi::Scene room = gi::quad_room(1000);
  const gi::Bvh bvh = gi::build_bvh(room);
  const gi::FastBvh fast = gi::make_fast_bvh(bvh, room, {4, 12, gi::Split::Sah, gi::WideCollapse::LargestFirst});
  EXPECT_EQ(sizeof(gi::FastBvhNode), 256u);
  std::size_t interior = 0, leaves = 0, children = 0;
  for (const gi::BvhNode& node : bvh.nodes) (node.count > 0 ? leaves : interior) += 1;
  for (const gi::FastBvhNode& node : fast.nodes)
    for (int c = 0; c < gi::wide_width; ++c) children += node.index[c] >= 0;
  EXPECT_EQ(children, fast.nodes.size() - 1 + leaves) << "every wide node and every leaf is one node's child once";
  EXPECT_LE(3 * fast.nodes.size(), interior) << "a wide node should open three binary nodes or more, on average";
  EXPECT_GE(7 * fast.nodes.size(), interior) << "a wide node opens at most seven binary ones";
  EXPECT_EQ(fast.refs.size(), bvh.refs.size());
}

TEST(FastBvh, SameHitsAsThePlainWalkInTheQuadRoom) {
  expect_same_hits(gi::quad_room(3000), hard_rays({-5, 0, -5}, {5, 3.5, 5}, 20000, 1), 15000);
}

TEST(FastBvh, SameHitsOnTheTreeMakeWorldBuilds) {
  // The binary tree down to one quad a leaf, its subtrees of up to four quads merged
  // into leaves where the SAH collapse says: a merged leaf tests its quads in the
  // order the plain walk's leaves would, left to right.
  const gi::Scene room = gi::quad_room(3000);
  const gi::Bvh bvh = gi::build_bvh(room, {1, 12, gi::Split::Sah});
  const gi::FastBvh fast = gi::make_fast_bvh(bvh, room, {4, 12, gi::Split::Sah, gi::WideCollapse::Sah});
  int merged = 0;
  for (const gi::FastBvhNode& node : fast.nodes)
    for (int c = 0; c < gi::wide_width; ++c) merged += node.count[c] > 1;
  EXPECT_GT(merged, 50) << "the collapse should merge some leaves";
  expect_same_hits(room, hard_rays({-5, 0, -5}, {5, 3.5, 5}, 20000, 5), 15000, {1, 12, gi::Split::Sah},
                   {4, 12, gi::Split::Sah, gi::WideCollapse::Sah});
}

TEST(FastBvh, SameHitsWithTheLargestChildOpenedFirst) {
  expect_same_hits(gi::quad_room(3000), hard_rays({-5, 0, -5}, {5, 3.5, 5}, 8000, 6), 6000, {},
                   {4, 12, gi::Split::Sah, gi::WideCollapse::LargestFirst});
}

TEST(FastBvh, SameHitsWithOneQuadPerLeafAndMedianSplits) {
  expect_same_hits(gi::quad_room(2000), hard_rays({-5, 0, -5}, {5, 3.5, 5}, 8000, 2), 6000,
                   {1, 12, gi::Split::Median});
}

TEST(FastBvh, SameHitsOnSpheresFarFromTheOrigin) {
  // Coordinates near 1000: the float origin is 2^-24 * 1000 off, which the widening covers.
  gi::Scene scene = gi::random_spheres(3000, 3);
  for (gi::Sphere& s : scene.spheres) s.center += vec3(1000, -700, 300);
  expect_same_hits(scene, hard_rays(vec3(1000 - 6, -700 - 6, 300 - 6), vec3(1000 + 6, -700 + 6, 300 + 6), 8000, 3),
                   1000);
}

TEST(FastBvh, ATreeThatIsOneLeafAndAnEmptyTree) {
  gi::Scene scene;
  const int m = scene.add(gi::Material{});
  scene.add(gi::Sphere{{0, 0, -5}, 1, m});
  scene.add(gi::Quad{{-1, -1, -3}, {2, 0, 0}, {0, 0.5, 0}, m});  // below the ray along the axis
  expect_same_hits(scene, hard_rays(vec3(-1.5), vec3(1.5), 2000, 4), 20);
  Ray ray{{0, 0, 0}, {0, 0, -1}};
  const auto hit = gi::closest_hit(gi::make_fast_bvh(gi::build_bvh(scene), scene), scene, ray);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 4.0);  // the sphere's near side
  const gi::Scene empty;
  Ray miss{{0, 0, 0}, {0, 0, -1}};
  EXPECT_FALSE(gi::closest_hit(gi::make_fast_bvh(gi::build_bvh(empty), empty), empty, miss));
  EXPECT_FALSE(gi::any_hit(gi::make_fast_bvh(gi::build_bvh(empty), empty), empty, miss));
}

TEST(FastBvh, SameHitsOnTheCameraRaysOfS10) {
  const gi::Scene scene = gi::make_scene("s10");
  const gi::CameraFrame frame = gi::camera_frame(scene.camera, 80, 60);
  std::vector<Ray> rays;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 80; ++x) rays.push_back(gi::primary_ray(frame, x + 0.5, y + 0.5));
  gi::Scene spheres_only = scene;
  spheres_only.planes.clear();  // the tree holds the spheres; a plane would hit every ray below the horizon
  const gi::Bvh bvh = gi::build_bvh(spheres_only);
  const gi::FastBvh fast = gi::make_fast_bvh(bvh, spheres_only);
  gi::TraversalCounts counts;
  int hits = 0;
  for (const Ray& ray : rays) {
    Ray a = ray, b = ray;
    const auto p = gi::closest_hit(bvh, spheres_only, a, counts), f = gi::closest_hit(fast, spheres_only, b);
    ASSERT_EQ(f.has_value(), p.has_value());
    if (p) {
      EXPECT_EQ(f->t, p->t);
    }
    hits += p.has_value();
  }
  EXPECT_GT(hits, 100);
}
