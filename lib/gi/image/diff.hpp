#pragma once
#include <vector>

#include "gi/image/image.hpp"

namespace gi {

// A false-colour map of scalar values: lo is black, then blue, green, yellow and
// red at hi (values outside are clamped). Heat maps of samples per pixel, errors ...
Image false_colour(const std::vector<double>& values, int width, int height, double lo, double hi);

// |a - b| per pixel (mean over channels) in false colour. scale is the difference
// shown as full red; 0 picks the largest difference in the images.
Image difference_image(const Image& a, const Image& b, double scale = 0);

Image crop(const Image& image, int x, int y, int w, int h);  // throws if outside
Image enlarge(const Image& image, int factor);                // nearest neighbour
// Images in one row, top-aligned, separated by `gap` pixels of `gap_colour`.
Image side_by_side(const std::vector<Image>& images, int gap = 4, Pixel gap_colour = Pixel(1));

}  // namespace gi
