#pragma once
#include <functional>

#include "gi/core/math.hpp"

namespace gi {

struct AdaptiveSample {
  Color colour;  // the box-filtered pixel value
  int samples;   // eye rays traced
};

// Whitted's adaptive supersampling of one pixel (the unit square): trace its four
// corners; where they differ by more than `threshold` (should_subdivide), trace the
// centre and the edge midpoints and treat the four quarters the same way, at most
// `max_subdivisions` levels deep. A square that is not split is worth the mean of
// its corners; the pixel is the area-weighted mean of its squares.
AdaptiveSample adaptive_sample(const std::function<Color(vec2)>& radiance, double threshold, int max_subdivisions);

}  // namespace gi
