#pragma once
#include <string>
#include <vector>

#include "gi/scene/scene_changes.hpp"

namespace gi {

// The text of the scene options a lesson takes (gi::Lesson adds them).

// --camera EYE:LOOK_AT[:FOV], each point three numbers "x,y,z" and FOV the vertical
// field of view in degrees: "278,273,-800:278,273,0:40". Throws OptionError naming
// what is wrong.
CameraChange parse_camera_change(const std::string& text);

// --light-scale NAME=FACTOR[,NAME=FACTOR ...]: "light=2" or "lamp=0.5,window=0",
// each name once, each factor in [0, 1e6]. Throws OptionError.
std::vector<LightScale> parse_light_scales(const std::string& text);

// A scene's name made safe as part of a file name: letters, digits, '-' and '_'
// kept, anything else '_' ("my room!" -> "my_room_"); "scene" if that leaves nothing.
std::string file_stem(const std::string& name);

}  // namespace gi
