#pragma once
// Where one shading point's shadow rays meet the light, read from the film's number
// sequence. The n x n shadow rays of one hit are one set of N = n^2 numbers of the
// sequence, at a dimension of their own for each depth and light:
//   Independent  the pixel's stream, in the order the tracer has always drawn it: the
//                pictures made before the sequences reached the tracer, to the byte
//   Stratified   the set is N jittered points (sample_stream.hpp): Random light sampling
//                becomes jittered sampling, with its strata in a random order
//   Sobol        the set is the next N points of the pixel's scrambled Sobol' sequence
//                for that dimension: a (0,m,2)-net when N = 2^m, and with every
//                further eye ray of the pixel the union stays a net
// Random takes the set's points as they are; Jittered keeps its cells and takes the
// offset within cell k from point k, so its offsets are spread across the cells too.
// The hit of eye-ray sample s reads set s: numbers sN .. sN + N - 1. A reflected and a
// refracted ray at one depth read the same set; each branch alone is still a uniform
// estimate, so each stays unbiased.
#include <cstdint>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/raytrace/soft_shadows.hpp"
#include "gi/render/render_pass.hpp"

namespace gi {

// The dimension of the shadow rays to area light `light` (of `lights`) at `depth`:
// after the pixel's and the lens's dimensions, one per (depth, light).
constexpr std::uint32_t shadow_dimension(int depth, int light, int lights) {
  return lens_dimension + 1 + static_cast<std::uint32_t>(depth * lights + light);
}

// The points in the light's unit square for one hit, as light_samples(settings, rng)
// places them, read from `sample`'s sequence at `dimension`.
std::vector<vec2> light_samples(const SoftShadowSettings& settings, PixelSample& sample, std::uint32_t dimension);

}  // namespace gi
