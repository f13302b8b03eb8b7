#pragma once
// Lesson 15: the runs every step reads -- each radiosity recipe of the course and path
// tracing at 1, 2, 4, ... spp on the Cornell box, each picture timed and scored against
// the stored truth (runs.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace lesson15 {

struct Settings {
  int size = 128, max_spp = 32, caustic_spp = 64, threads = 0;
  bool full = false;
  std::uint64_t seed = 1;
  std::string reference;
};

// One point of the chart: a method's picture, its error against the truth and its time.
struct Run {
  std::string family, name;
  int elements = 0;  // 0: path tracing
  double seconds = 0;
  double error = 0;        // relative RMS over the interior blocks (picture_error.hpp)
  double pixel_error = 0;  // the same over single interior pixels: what the eye sees of noise
  gi::Image picture;
};

// The two masks a picture is scored over: blocks (the course's measure, lesson 12's) and
// single pixels, with the reference's own error by each.
struct Scoring {
  gi::BlockMask blocks, pixels;
  double noise = 0, pixel_noise = 0;
};

// Every radiosity recipe (radiosity_methods in runs.cpp; more meshes with s.full),
// each from the scene to the picture, scored.
std::vector<Run> solve_radiosity(const gi::RadiosityScene& scene, const Settings& s, const gi::Truth& truth,
                                 const Scoring& scoring);

// Path tracing (MIS) at 1, 2, 4, ... spp, one film sampled further for each picture.
std::vector<Run> path_trace(const gi::PathScene& scene, const Settings& s, const gi::Truth& truth,
                            const Scoring& scoring);

}  // namespace lesson15
