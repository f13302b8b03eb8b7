#pragma once
#include <vector>

#include "gi/image/image.hpp"
#include "gi/pathtrace/path_scene.hpp"

namespace gi {

// Veach and Guibas 1995 ("Optimally combining sampling techniques for Monte Carlo
// rendering"), their figure of MIS: four glossy plates, each tilted so that the camera
// sees in it the reflection of a row of four spherical lights. The plates run from
// nearly a mirror at the back (top of the picture) to rough at the front; the lights
// from small on the left to large on the right, radius x3 each, all of the same power
// (L_e r^2 the same). Each plate is a Phong lobe (bsdf.hpp, Glossy) and nothing else;
// a dim sky lets the plates be seen between the highlights.
//
// Which strategy sees a highlight well depends on the lobe's width against the light's
// angular size: a lobe narrower than the light is found by BSDF sampling (almost every
// direction it draws lands on the light), a light smaller than the lobe by light sampling
// (almost every point it draws lies inside the lobe).
inline constexpr int plate_count = 4, plate_light_count = 4;
inline constexpr double plate_exponents[plate_count] = {80000, 4000, 200, 10};  // back to front
inline constexpr double plate_light_radii[plate_light_count] = {1.0 / 30, 0.1, 0.3, 0.9};  // left to right

// Materials: the plates' are 0..3 (back to front), quads 0..3; the lights are spheres 0..3.
Scene veach_plates_scene();

// The pixels of a width x height picture (row-major, 1 = in) whose eye ray through the
// pixel's centre meets a plate first: where the strategies differ (a light seen directly
// is the same in all three, up to where in the pixel its rays fall).
std::vector<char> plates_mask(const PathScene& scene, int width, int height);

// The pixels of a width x height picture (row-major, 1 = in) where the eye ray through
// any of 4 x 4 points of the pixel meets `plate` first, and its mirror direction there
// points within the light's angular radius plus the lobe's half-width (where cos^n falls
// to 1/10) of `light`'s centre: where that plate shows that light's highlight, however
// small (the sharpest plate's are smaller than a pixel).
std::vector<char> highlight_mask(const PathScene& scene, int width, int height, int plate, int light);

// Each pixel's error in proportion to the light there, in grey (the mean of the channels):
//   e_i = |t_i - r_i| / (r_i + epsilon)
// epsilon, the sky's radiance, keeps the dark from dividing by nearly zero. Every pixel
// counts alike, so a wide rough highlight weighs as much as it covers, a bright pinpoint
// as little. Throws std::invalid_argument for pictures of different sizes.
std::vector<double> relative_error_map(const Image& test, const Image& reference, double epsilon);

// The RMS of such errors over a mask's pixels, sqrt(mean e_i^2); every pixel when the mask
// is empty. Throws std::invalid_argument for a mask of another size or with no pixel.
double rms_over(const std::vector<double>& errors, const std::vector<char>& mask = {});

}  // namespace gi
