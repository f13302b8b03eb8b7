#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh.hpp"

namespace gi {

// The Cornell box (www.graphics.cornell.edu/online/box/data.html), its measured
// geometry in millimetres, as published:
//  - the camera looks along +z with +y up from (278, 273, -800); in our right-handed
//    camera, +x is then on the image's left, so the red wall at x ~ 556 is on the
//    left, as in the photographs;
//  - the floor, ceiling and left wall are not rectangles (x runs 549.6 to 556), kept
//    as given: every surface is a general quadrilateral;
//  - the light is flush with the ceiling; the ceiling is cut into four pieces around
//    it so that nothing overlaps;
//  - reflectances are spectra in the data; we use the RGB set of Morgan McGuire's
//    Computer Graphics Archive version (white 0.725 0.71 0.68, red 0.63 0.065 0.05,
//    green 0.14 0.45 0.091; light radiance 17 12 4, so exitance E = pi L), which many
//    renderers share; the light's own reflectance is 0.78;
//  - the box is open at the front (z = 0), where the camera looks in: light leaves
//    there, so rows of F sum below 1. `closed` adds a black front wall (rho = 0),
//    which absorbs exactly what the opening lets out but makes every row sum to 1:
//    the form of the box to test conservation on.
RadiosityScene cornell_box(bool closed = false);

// The smallest scenes that show one effect each; sizes in metres.
RadiosityScene parallel_squares(double side = 1.0, double distance = 1.0);    // two opposed squares
RadiosityScene perpendicular_squares(double side = 1.0);                      // sharing an edge
RadiosityScene closed_box(double side = 1.0);  // six inward faces: every row of F sums to 1
RadiosityScene open_box(double side = 1.0);    // the same without its top: rows sum below 1
RadiosityScene occluded_squares(double side = 1.0, double distance = 2.0);   // a blocker in between

std::vector<std::string> radiosity_scene_names();
RadiosityScene make_radiosity_scene(const std::string& name);  // throws std::invalid_argument

}  // namespace gi
