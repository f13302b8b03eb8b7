#include "gi/raytrace/render.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/camera.hpp"

TEST(Render, SameImageAndCountsForAnyThreadCount) {
  const gi::World world = gi::make_world(gi::make_scene("whitted"));
  gi::RenderSettings settings;
  settings.width = 97;  // not a multiple of the tile size
  settings.height = 61;
  for (gi::Sampling sampling : {gi::Sampling{}, gi::Sampling{gi::Sampler::Jittered, 3},
                                gi::Sampling{gi::Sampler::Adaptive, 1, 0.05, 3}}) {
    settings.sampling = sampling;
    const gi::RenderResult one = gi::render(world, settings, 1, 1);
    if (sampling.sampler == gi::Sampler::Centre) {
      EXPECT_EQ(one.counts.of(gi::RayKind::Primary), 97u * 61u);
    }
    for (int threads : {2, 3, 7}) {
      const gi::RenderResult many = gi::render(world, settings, 1, threads);
      EXPECT_EQ(many.image.pixels, one.image.pixels) << threads << " threads";
      EXPECT_EQ(many.samples, one.samples) << threads << " threads";
      EXPECT_EQ(many.counts.total(), one.counts.total()) << threads << " threads";
    }
  }
}

TEST(Render, DeeperRecursionCastsMoreSecondaryRays) {
  const gi::World world = gi::make_world(gi::make_scene("whitted"));
  gi::RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.trace.max_depth = 0;
  EXPECT_EQ(gi::render(world, settings, 1, 0).counts.of(gi::RayKind::Reflected), 0u);
  settings.trace.max_depth = 4;
  const gi::RenderResult deep = gi::render(world, settings, 1, 0);
  EXPECT_GT(deep.counts.of(gi::RayKind::Reflected), 0u);
  EXPECT_GT(deep.counts.of(gi::RayKind::Transmitted), 0u);
  EXPECT_EQ(deep.counts.at_depth(5), 0u);
}

TEST(Render, BadSettingsAreRejected) {
  const gi::World world = gi::make_world(gi::make_scene("spheres"));
  gi::RenderSettings settings;
  settings.width = -1;
  EXPECT_THROW(gi::render(world, settings, 1, 0), std::invalid_argument);
  settings.width = 10;
  settings.trace.max_depth = 1000;
  EXPECT_THROW(gi::render(world, settings, 1, 0), std::invalid_argument);
  settings.trace.max_depth = 3;
  settings.trace.min_contribution = NAN;
  EXPECT_THROW(gi::render(world, settings, 1, 0), std::invalid_argument);
}

// render() is trace() through every pixel's centre, pixel i drawing from stream i of
// the seed: bit for bit what a plain loop over the pixels gives. The soft scene's area
// lights draw from each pixel's random stream, so a stream seeded for the wrong pixel
// changes the picture too.
TEST(Render, CentresAreTracePerPixelBitForBit) {
  for (const char* scene : {"s10", "soft"}) {
    const gi::World world = gi::make_world(gi::make_scene(scene), gi::Acceleration::BruteForce);
    gi::RenderSettings settings;
    settings.width = 70;  // two whole tiles and a part one
    settings.height = 45;
    ASSERT_EQ(settings.sampling.sampler, gi::Sampler::Centre);
    const gi::RenderResult rendered = gi::render(world, settings, 5, 1);

    const gi::CameraFrame frame = gi::camera_frame(world.scene.camera, settings.width, settings.height);
    gi::RayCounts counts;
    int differ = 0;
    for (int y = 0; y < settings.height; ++y) {
      for (int x = 0; x < settings.width; ++x) {
        const std::size_t pixel = static_cast<std::size_t>(y) * settings.width + x;
        gi::Rng rng(5, pixel);
        counts.count(gi::RayKind::Primary, 0);
        const gi::Pixel plain(gi::trace(world, gi::primary_ray(frame, x + 0.5, y + 0.5), settings.trace, counts, rng));
        differ += plain != rendered.image.pixels[pixel] || rendered.samples[pixel] != 1;
      }
    }
    EXPECT_EQ(differ, 0) << scene << ": pixels where render() differs from trace() per pixel";
    EXPECT_EQ(rendered.counts.at, counts.at) << scene << ": ray counts by kind and depth";
    EXPECT_GT(counts.of(gi::RayKind::Shadow), 0u) << scene;
  }
}


// The tracer on the fast queries and local shading (TraceSettings::fast_queries,
// world_fast.hpp, whitted_fast.hpp) gives the plain tracer's picture to the byte and its
// ray counts, whatever the acceleration and the thread count.
TEST(Render, FastQueriesGiveTheSamePictureAndCounts) {
  for (const char* scene : {"s10", "soft", "whitted"}) {
    for (gi::Acceleration acceleration : {gi::Acceleration::BruteForce, gi::Acceleration::Bvh, gi::Acceleration::FastBvh}) {
      const gi::World world = gi::make_world(gi::make_scene(scene), acceleration);
      gi::RenderSettings settings;
      settings.width = 80;
      settings.height = 60;
      settings.trace.max_depth = 8;
      const gi::RenderResult plain = gi::render(world, settings, 3, 1);
      settings.trace.fast_queries = true;
      const gi::RenderResult fast = gi::render(world, settings, 3, 2);
      EXPECT_EQ(fast.image.pixels, plain.image.pixels) << scene << ", " << gi::name(acceleration);
      EXPECT_EQ(fast.counts.at, plain.counts.at) << scene << ", " << gi::name(acceleration);
      EXPECT_GT(plain.counts.of(gi::RayKind::Shadow), 0u) << scene;
    }
  }
}
