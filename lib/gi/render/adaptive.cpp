#include "gi/render/adaptive.hpp"

#include <array>

#include "gi/render/pixel_samplers.hpp"

namespace gi {

namespace {

// The square [x0, x0 + size] x [y0, y0 + size] with its corner radiances
// c[0] = (x0, y0), c[1] = (x1, y0), c[2] = (x0, y1), c[3] = (x1, y1).
Color refine(const std::function<Color(vec2)>& radiance, vec2 origin, double size, const std::array<Color, 4>& c,
             double threshold, int levels_left, int& samples) {
  if (levels_left == 0 || !should_subdivide(c, threshold)) return 0.25 * (c[0] + c[1] + c[2] + c[3]);
  const double h = 0.5 * size;
  // Five new points: the centre and the middle of each edge; the corners are reused.
  const Color top = radiance(origin + vec2(h, 0)), left = radiance(origin + vec2(0, h));
  const Color centre = radiance(origin + vec2(h, h));
  const Color right = radiance(origin + vec2(size, h)), bottom = radiance(origin + vec2(h, size));
  samples += 5;
  const int next = levels_left - 1;
  return 0.25 * (refine(radiance, origin, h, {c[0], top, left, centre}, threshold, next, samples) +
                 refine(radiance, origin + vec2(h, 0), h, {top, c[1], centre, right}, threshold, next, samples) +
                 refine(radiance, origin + vec2(0, h), h, {left, centre, c[2], bottom}, threshold, next, samples) +
                 refine(radiance, origin + vec2(h, h), h, {centre, right, bottom, c[3]}, threshold, next, samples));
}

}  // namespace

AdaptiveSample adaptive_sample(const std::function<Color(vec2)>& radiance, double threshold, int max_subdivisions) {
  const std::array<Color, 4> corners = {radiance(vec2(0, 0)), radiance(vec2(1, 0)), radiance(vec2(0, 1)),
                                        radiance(vec2(1, 1))};
  int samples = 4;
  const Color colour = refine(radiance, vec2(0, 0), 1.0, corners, threshold, max_subdivisions, samples);
  return {colour, samples};
}

}  // namespace gi
