// Shaft culling (shaft.hpp): the few triangles near a pair of patches must give every
// shadow ray between them the answer the whole scene gives.
#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/form_factors/shaft.hpp"

using gi::vec3;

namespace {

gi::FormFactorScene scene_of(const gi::RadiosityScene& scene) {
  std::vector<gi::Polygon> shapes;
  for (const gi::Surface& s : scene.surfaces) shapes.push_back(gi::make_polygon(s.corners));
  return gi::FormFactorScene(shapes);
}

std::vector<vec3> corners_of(const gi::Polygon& a, const gi::Polygon& b) {
  return {a.corners[0], a.corners[1], a.corners[2], a.corners[3],
          b.corners[0], b.corners[1], b.corners[2], b.corners[3]};
}

}  // namespace

// Every pair of the Cornell box's surfaces (blocks included), 64 random segments
// between random points of the two: the shaft's verdict is the whole scene's, ray by
// ray. The segments must meet blockers often (else the test shows nothing), and the
// shafts must hold fewer triangles than the scene (else they cull nothing).
TEST(Shaft, AgreesWithTheWholeSceneOnEverySegmentInTheCornellBox) {
  const gi::FormFactorScene scene = scene_of(gi::cornell_box());
  const std::vector<gi::Polygon>& p = scene.polygons();
  const int triangles = static_cast<int>(scene.world().scene.triangles.size());
  gi::Rng rng(7, 0);
  int segments = 0, blocked = 0, culled = 0, pairs = 0;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = 0; b < p.size(); ++b) {
      if (a == b) continue;
      const gi::Shaft shaft(scene, corners_of(p[a], p[b]));
      ++pairs;
      culled += shaft.candidates() < triangles / 2;
      for (int k = 0; k < 64; ++k) {
        const vec3 from = gi::bilinear(p[a].corners, rng.uniform(), rng.uniform());
        const vec3 to = gi::bilinear(p[b].corners, rng.uniform(), rng.uniform());
        const bool whole = scene.visible(from, to);
        ASSERT_EQ(shaft.visible(from, to), whole) << "surfaces " << a << " and " << b << ", segment " << k;
        ++segments, blocked += !whole;
      }
    }
  EXPECT_GT(blocked, segments / 20) << "too few segments meet a blocker to test the shaft";
  EXPECT_GT(culled, pairs / 2) << "most shafts should hold less than half the scene's triangles";
}

TEST(Shaft, HoldsOnlyWhatStandsBetween) {
  // Two unit squares facing each other 2 apart, a slab of two half-size squares
  // between them over one quarter: the slab's four triangles are in the shaft, the
  // squares' own are not (every corner is on one side of them).
  const gi::FormFactorScene scene = scene_of(gi::occluded_squares());
  const std::vector<gi::Polygon>& p = scene.polygons();
  ASSERT_EQ(p.size(), 4u);
  const gi::Shaft between(scene, corners_of(p[0], p[1]));
  EXPECT_EQ(between.candidates(), 4);
  EXPECT_FALSE(between.visible({0.25, 0, 0.25}, {0.25, 2, 0.25})) << "through the slab";
  EXPECT_TRUE(between.visible({0.75, 0, 0.75}, {0.75, 2, 0.75})) << "beside the slab";
  // Between two walls of an empty box nothing can stand in the way.
  const gi::FormFactorScene box = scene_of(gi::closed_box());
  const std::vector<gi::Polygon>& walls = box.polygons();
  const gi::Shaft across(box, corners_of(walls[0], walls[1]));
  EXPECT_EQ(across.candidates(), 0);
  EXPECT_TRUE(across.visible(walls[0].centre, walls[1].centre));
}
