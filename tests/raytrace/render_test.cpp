#include "gi/raytrace/render.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/camera.hpp"

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

// render() traces one eye ray per pixel centre on a path of its own, each eye ray made
// a pixel ahead (render.cpp): it must give, bit for bit, what sample_pixel gives with
// one trace() per pixel. The soft scene's area lights draw from each pixel's random
// stream, so a stream seeded for the wrong pixel changes the picture too.
TEST(Render, CentreRowsAreSamplePixelsBitForBit) {
  for (const char* scene : {"s10", "soft"}) {
    const gi::World world = gi::make_world(gi::make_scene(scene), gi::Acceleration::BruteForce);
    gi::RenderSettings settings;
    settings.width = 70;  // two whole tiles and a part one
    settings.height = 45;
    settings.threads = 1;
    ASSERT_EQ(settings.sampling.sampler, gi::Sampler::Centre);
    const gi::RenderResult fast = gi::render(world, settings);

    const gi::CameraFrame frame = gi::camera_frame(world.scene.camera, settings.width, settings.height);
    gi::RayCounts counts;
    gi::Rng rng;
    const std::function<gi::Color(double, double)> radiance = [&](double px, double py) {
      counts.count(gi::RayKind::Primary, 0);
      return gi::trace(world, gi::primary_ray(frame, px, py), settings.trace, counts, rng);
    };
    int differ = 0;
    for (int y = 0; y < settings.height; ++y) {
      for (int x = 0; x < settings.width; ++x) {
        const std::size_t pixel = static_cast<std::size_t>(y) * settings.width + x;
        rng = gi::Rng(settings.seed, pixel);
        int samples = 0;
        const gi::Pixel plain(gi::sample_pixel(settings.sampling, x, y, rng, radiance, samples));
        differ += plain != fast.image.pixels[pixel] || samples != fast.samples[pixel];
      }
    }
    EXPECT_EQ(differ, 0) << scene << ": pixels where the centre path differs from sample_pixel";
    EXPECT_EQ(fast.counts.at, counts.at) << scene << ": ray counts by kind and depth";
    EXPECT_GT(counts.of(gi::RayKind::Shadow), 0u) << scene;
  }
}
