#pragma once
// Lesson 13: what every step shares -- the box, its truth and how a hierarchical
// solution is drawn and scored (scoring.cpp).
#include <cstdint>
#include <string>

#include "gi/image/image.hpp"
#include "gi/radiosity/display/direct_display.hpp"
#include "gi/radiosity/display/surface_mask.hpp"
#include "gi/radiosity/hierarchical/hierarchical_run.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

namespace lesson13 {


// Every picture is the published camera's at the stored truth's size, scored against
// the converged path-traced picture of the same box (lessons/references/, made by
// 14_make_reference): relative RMS over the 8 x 8 blocks that lie on one surface other
// than the light (picture_error.hpp), as lesson 12 scores every uniform method.
struct Setup {
  gi::RadiosityScene scene;
  gi::HierarchicalSettings settings;  // exact direct light on: the lesson's default method
  gi::DisplaySettings display;
  gi::DirectLightSettings per_pixel;  // the direct light drawn per pixel (lesson 12's split)
  // That light depends on the surfaces, not on how they are meshed: cast on the
  // surfaces themselves, its time counted in every picture that shows it.
  const gi::DirectRadiance* direct = nullptr;
  gi::Image truth;
  gi::BlockMask mask;
  double exposure = 1.5;
  int threads = 0;
  std::uint64_t seed = 1;  // the display's films
  int uniform_elements = 1000;  // the finest uniform mesh of the comparison; also a quarter of it
};

// How a hierarchical solution is shown: all its light on the leaves (Gouraud, no
// cracks), or lesson 12's split -- the exact direct light at every eye ray, and only
// what has bounced more than once, B - E - D, from the leaves -- or the same split with
// B - E - D gathered over the links at the leaves' corners (the final gather,
// link_gather.hpp).
enum class Shown { Leaves, DirectPerPixel, Gathered };

struct Scored {
  gi::Image picture;
  double seconds = 0;  // the per-pixel direct light's: part of the answer, so it counts
  double error = 0;    // relative RMS against the truth
};

// The solution drawn as `shown` through the box's camera, and its error against the truth.
Scored score(const Setup& s, const gi::HierarchicalRun& run, Shown shown);

// `s` with the link threshold BF_eps and the direct light exact or by links.
gi::HierarchicalSettings with(gi::HierarchicalSettings s, double bf_eps, bool exact_direct);

}  // namespace lesson13
