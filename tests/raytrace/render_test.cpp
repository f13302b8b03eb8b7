#include "gi/raytrace/render.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/scene/builtin_scenes.hpp"

TEST(Render, SameImageAndCountsForAnyThreadCount) {
  const gi::World world = gi::make_world(gi::make_scene("whitted"));
  gi::RenderSettings settings;
  settings.width = 97;  // not a multiple of the tile size
  settings.height = 61;
  settings.threads = 1;
  const gi::RenderResult one = gi::render(world, settings);
  EXPECT_EQ(one.counts.of(gi::RayKind::Primary), 97u * 61u);
  for (int threads : {2, 3, 7}) {
    settings.threads = threads;
    const gi::RenderResult many = gi::render(world, settings);
    EXPECT_EQ(many.image.pixels, one.image.pixels) << threads << " threads";
    EXPECT_EQ(many.counts.total(), one.counts.total()) << threads << " threads";
  }
}

TEST(Render, DeeperRecursionCastsMoreSecondaryRays) {
  const gi::World world = gi::make_world(gi::make_scene("whitted"));
  gi::RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.trace.max_depth = 0;
  EXPECT_EQ(gi::render(world, settings).counts.of(gi::RayKind::Reflected), 0u);
  settings.trace.max_depth = 4;
  const gi::RenderResult deep = gi::render(world, settings);
  EXPECT_GT(deep.counts.of(gi::RayKind::Reflected), 0u);
  EXPECT_GT(deep.counts.of(gi::RayKind::Transmitted), 0u);
  EXPECT_EQ(deep.counts.at_depth(5), 0u);
}

TEST(Render, BadSettingsAreRejected) {
  const gi::World world = gi::make_world(gi::make_scene("spheres"));
  gi::RenderSettings settings;
  settings.width = -1;
  EXPECT_THROW(gi::render(world, settings), std::invalid_argument);
  settings.width = 10;
  settings.trace.max_depth = 1000;
  EXPECT_THROW(gi::render(world, settings), std::invalid_argument);
  settings.trace.max_depth = 3;
  settings.trace.min_contribution = NAN;
  EXPECT_THROW(gi::render(world, settings), std::invalid_argument);
}
