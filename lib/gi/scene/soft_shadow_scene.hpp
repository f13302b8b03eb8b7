#pragma once
#include "gi/scene/scene.hpp"

namespace gi {

// Lesson 04's scene: a box, a ball and a thin pole on a grey floor under a square
// horizontal area light of side `light_size` centred at (light_x, H, light_z) (size 0
// makes it a point light there: hard shadows). The box's top edge x = 1.5 at height
// h = 1 runs parallel to the light's edges, so on the floor line z = 0 its shadow
// has a penumbra centred at x_c = light_x + (1.5 - light_x) H / (H - h), of width
//   w = light_size * h / (H - h)   (= light_size / 3)
// by similar triangles, across which the visible part of the light grows linearly.
Scene soft_shadow_scene(double light_size);

inline constexpr double soft_shadow_light_x = -1.0;
inline constexpr double soft_shadow_light_z = 1.0;
inline constexpr double soft_shadow_light_height = 4.0;  // H
inline constexpr double soft_shadow_box_height = 1.0;    // h
inline constexpr double soft_shadow_box_edge_x = 1.5;    // the edge that casts the measured shadow

}  // namespace gi
