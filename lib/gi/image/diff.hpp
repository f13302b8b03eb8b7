#pragma once
#include <vector>

#include "gi/image/image.hpp"

namespace gi {

// A false-colour map of scalar values: lo is black, then blue, green, yellow and
// red at hi (values outside are clamped). Heat maps of samples per pixel, errors ...
Image false_colour(const std::vector<double>& values, int width, int height, double lo, double hi);
// The ramp false_colour draws, evenly spaced from lo to hi, and its name; a colour
// bar beside a picture is drawn from these (report/report_page.cpp).
inline constexpr Pixel false_colour_stops[] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
inline constexpr const char* false_colour_map_name = "black, blue, green, yellow, red";

// |a - b| per pixel (mean over channels) in false colour. scale is the difference
// shown as full red; 0 picks the largest difference in the images.
Image difference_image(const Image& a, const Image& b, double scale = 0);
// The largest |a - b| (mean over channels) of any pixel: the red of difference_image
// with scale 0.
double largest_difference(const Image& a, const Image& b);

Image crop(const Image& image, int x, int y, int w, int h);  // throws if outside
Image enlarge(const Image& image, int factor);                // nearest neighbour
// Images in one row, top-aligned, separated by `gap` pixels of `gap_colour`.
Image side_by_side(const std::vector<Image>& images, int gap = 4, Pixel gap_colour = Pixel(1));
// Images in rows of `columns` (the last row may be shorter), read left to right and top
// to bottom, rows top-aligned and separated as side_by_side separates the images.
Image image_grid(const std::vector<Image>& images, int columns, int gap = 4, Pixel gap_colour = Pixel(1));

}  // namespace gi
