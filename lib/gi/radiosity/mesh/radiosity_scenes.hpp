#pragma once
#include <string>
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"

namespace gi {

// The Cornell box of gi/scene/cornell_box.hpp (its data, palette and camera are
// described there), its surfaces taken as they are: general quadrilaterals in
// millimetres, the light with its exitance E = pi L. `closed` adds a black front
// wall: every row of F then sums to 1, the form of the box to test conservation on.
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
