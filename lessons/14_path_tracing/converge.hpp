#pragma once
// Lesson 14: the lesson's settings, and one sampling strategy run sample after sample
// on one film, a snapshot at every power of two (converge.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "gi/core/samplers/sample_stream.hpp"
#include "gi/image/image.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/lesson.hpp"

namespace lesson14 {

struct Settings {
  int width = 128, height = 128, max_spp = 128, reference_spp = 1024, threads = 0;
  std::uint64_t seed = 1;
  std::string scene = "cornell", reference;
  gi::PathSettings path;
  gi::SamplerKind sequence = gi::SamplerKind::Independent;  // --sampler: the numbers the paths read
};

// The mean over the channels, and over the picture.
double grey(const gi::Pixel& p);
double mean_of(const gi::Image& image);

// One strategy, sample after sample: snapshots at 1, 2, 4, ... spp with the time so far.
struct Snapshot {
  int spp;
  double seconds, rmse, relative, variance;
};

// The snapshots of `strategy` at 1, 2, 4, ... s.max_spp, measured against `reference`.
// With `pictures`, also the pictures at 1, 4, 16, ... spp, the last one's relative
// error per pixel, the progression beside the reference, and the reference itself.
std::vector<Snapshot> converge(const gi::PathScene& scene, const Settings& s, gi::Strategy strategy,
                               const gi::Truth& reference, gi::Lesson* pictures);

}  // namespace lesson14
