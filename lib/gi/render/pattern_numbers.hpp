#pragma once
// Where lesson 03's random patterns put a pixel's eye rays, read from the film's number
// sequence at the pixel's dimension (pixel_dimension), eye ray k of the pass being the
// pixel's sample first + k:
//   Independent  the pixel's stream, drawn as random_positions and jittered_positions
//                draw it, the whole pattern before any ray is traced: the pictures made
//                before the sequences reached the patterns, to the byte
//   otherwise    Random takes the sequence's points as they are, so Random with the
//                stratified sequence is a jittered pattern; Jittered keeps its n x n
//                cells and takes the offset in cell k from point k, so the offsets are
//                themselves spread across the cells
#include <vector>

#include "gi/core/math.hpp"
#include "gi/render/pixel_samplers.hpp"
#include "gi/render/render_pass.hpp"

namespace gi {

// Replaces `points` by the n x n points of a Random or Jittered pass of sample's pixel,
// starting at its sample sample.index (left as it was).
void pattern_points(const Sampling& sampling, PixelSample& sample, std::vector<vec2>& points);

}  // namespace gi
