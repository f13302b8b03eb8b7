#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/scene/builtin_scenes.hpp"

using gi::vec3;

TEST(Scene, AddersRejectMissingMaterialsAndBadShapes) {
  gi::Scene scene;
  EXPECT_THROW(scene.add(gi::Sphere{{0, 0, 0}, 1, 0}), std::invalid_argument);  // no material 0 yet
  const int m = scene.add(gi::Material{});
  EXPECT_THROW(scene.add(gi::Sphere{{0, 0, 0}, -1, m}), std::invalid_argument);
  gi::Material glass;
  glass.transmission = gi::Color(1);
  glass.ior = 0;
  EXPECT_THROW(scene.add(glass), std::invalid_argument);
  gi::Material nan_material;
  nan_material.diffuse.x = NAN;
  EXPECT_THROW(scene.add(nan_material), std::invalid_argument);
}

TEST(Scene, CheckerboardAlternatesAcrossZero) {
  gi::Material m;
  m.diffuse = gi::Color(1);
  m.checker_diffuse = gi::Color(0);
  m.checker_size = 1;
  EXPECT_EQ(gi::diffuse_at(m, {0.5, 0, 0.5}), gi::Color(1));
  EXPECT_EQ(gi::diffuse_at(m, {-0.5, 0, 0.5}), gi::Color(0));  // a cast to int would give 1 here
  EXPECT_EQ(gi::diffuse_at(m, {-0.5, 0, -0.5}), gi::Color(1));
  EXPECT_EQ(gi::diffuse_at(m, {1.5, 7, 0.5}), gi::Color(0));
}

TEST(Scene, BuiltInScenesAreValidAndUnknownNamesListTheKnownOnes) {
  for (const std::string& name : gi::scene_names()) {
    const gi::Scene scene = gi::make_scene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_NO_THROW(gi::check(scene));
    EXPECT_FALSE(scene.lights.empty() && scene.area_lights.empty()) << name << " has no light";
  }
  try {
    gi::make_scene("cornel");
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("whitted"), std::string::npos) << e.what();
  }
}

TEST(Scene, S10MatchesTheTachyonFile) {
  const gi::Scene s10 = gi::make_scene("s10");
  EXPECT_EQ(s10.spheres.size(), 10u);
  EXPECT_EQ(s10.planes.size(), 1u);
  EXPECT_EQ(s10.lights.size(), 2u);
  int mirrors = 0, glasses = 0;
  for (const auto& s : s10.spheres) {
    mirrors += gi::max_component(s10.materials[s.material].mirror) > 0;
    glasses += s10.materials[s.material].is_dielectric();
  }
  EXPECT_EQ(mirrors, 1);
  EXPECT_EQ(glasses, 1);
}
