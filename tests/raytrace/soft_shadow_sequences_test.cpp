// Whitted's soft shadows read their points on the light from the film's number
// sequence: the independent one gives the pictures made before, to the byte; the
// stratified and Sobol' sets stay unbiased, leave less noise in the penumbra, and give
// the same bytes on any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gi/core/hash.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/scene/soft_shadow_scene.hpp"

namespace {

std::string hash_of(const gi::Image& image) {
  const char* bytes = reinterpret_cast<const char*>(image.pixels.data());
  return gi::hex(gi::fnv1a({bytes, image.pixels.size() * sizeof(gi::Pixel)}));
}

gi::RenderSettings small_soft(gi::SoftShadowSettings shadows, gi::Sampling sampling) {
  gi::RenderSettings s;
  s.width = 48, s.height = 36;
  s.trace.max_depth = 1;
  s.trace.soft_shadows = shadows;
  s.sampling = sampling;
  return s;
}

}  // namespace

// The hashes were taken with the tracer that drew its shadow points straight from the
// pixel's stream, before the sequences reached it (the build's floating point is
// strict, -ffp-contract=off, so they hold on any compiler that keeps IEEE order).
TEST(SoftShadowSequences, IndependentNumbersGiveThePicturesMadeBefore) {
  const gi::World world = gi::make_world(gi::soft_shadow_scene(1.0));
  const struct {
    gi::SoftShadowSettings shadows;
    gi::Sampling sampling;
    const char* hash;
  } cases[] = {
      {{gi::LightSampling::Random, 2}, {gi::Sampler::Centre, 1}, "0f060c9f6fc45b66"},
      {{gi::LightSampling::Jittered, 3}, {gi::Sampler::Centre, 1}, "107b2f611c908ab6"},
      {{gi::LightSampling::Random, 2}, {gi::Sampler::Jittered, 2}, "ae717c6e1f6a68c1"},
      {{gi::LightSampling::Jittered, 2}, {gi::Sampler::Random, 2}, "ccb81a06bad13af7"},
  };
  for (const auto& c : cases) {
    const gi::Image image = gi::render(world, small_soft(c.shadows, c.sampling), 5, 2).image;
    EXPECT_EQ(hash_of(image), c.hash) << gi::light_sampling_name(c.shadows.sampling) << " " << c.shadows.n
                                      << ", pixels " << gi::sampler_name(c.sampling.sampler);
  }
}
