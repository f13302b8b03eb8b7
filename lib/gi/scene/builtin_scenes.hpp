#pragma once
#include <string>
#include <vector>

#include "gi/scene/scene.hpp"

namespace gi {

// The built-in scenes, written in code; each is also a scene file, lessons/scenes/NAME.json
// (scene_file.hpp), which renders the same bytes (tests/scene/scene_files_test.cpp):
//   whitted  Whitted's 1980 image: a mirror sphere and a glass sphere over a
//            red-and-yellow checkerboard
//   spheres  three shaded spheres on a grey floor, one light: the simplest picture
//   s10      ten spheres on a checkered plane, two lights, a mirror and a glass
//            sphere: the same scene as lessons/scenes/s10.tachyon.dat, for timing
//   aliasing a checkerboard to the horizon, poles and a wire thinner than a pixel
//   soft     a box, a ball and a pole under a 1 x 1 area light (soft_shadow_scene.hpp)
std::vector<std::string> scene_names();

// Throws std::invalid_argument naming the known scenes when `name` is not one.
Scene make_scene(const std::string& name);

}  // namespace gi
