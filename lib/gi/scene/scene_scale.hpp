#pragma once
#include "gi/scene/scene.hpp"

namespace gi {

// How large a scene is, for the rays that leave a surface.
//
// A hit point x = o + t d is computed in floating point, so it lies off the surface by
// round-off: a few parts in 10^16 of the size of the numbers in the sum, the ray's
// origin and the point itself. A ray that starts at x again may hit the surface it
// leaves (shadow acne) or start behind it, so it starts a little off it, along the
// normal: an offset epsilon. A fixed epsilon (1e-6 scene units) is round-off's size in
// no scene: the same room in metres, in millimetres (10^3 larger) or scaled by 1e-5
// draws different pictures -- at 1e-5 the offset is a hundredth of the room, so that
// shadow rays start past the blockers they should meet and shadows go missing.
//
// The offset is made relative instead. Two ways are known: pbrt bounds each hit's
// round-off from the magnitudes in its intersection routine (error bounds carried
// through every operation), and many renderers scale by one size per scene. The
// workbench takes the second: it needs no change to the intersection routines a
// student writes in labs 1 and 5, and its scale is one number computed once. The cost
// is that a detail smaller than about 10^-7 of the whole scene is below the offset (a
// thin wall there would let light through); the lessons' scenes have none.
//
// The scale is the largest coordinate, in size, of anything in the scene -- every
// primitive's bounds, the point and quad lights and the camera's eye, where the eye
// rays start -- rounded up to a power of two (2^e with the largest coordinate in
// [2^(e-1), 2^e)); 1 for an empty scene. A power of two because multiplying by it is
// exact: a scene scaled by 2^k gets offsets scaled by exactly 2^k and draws the very
// same bytes, and a scene scaled by 10^k the same picture within round-off.
//
// The offsets it sets (each site says how, with the scene it was first tuned on, whose
// bytes it keeps): Whitted's shadow, reflected and refracted rays (TraceSettings::
// epsilon, 1e-6 at Whitted's scale 16), the path tracer's bounces and light rays and
// the two-pass eye pass's (1e-9 of the coordinates plus 1e-9 of scale / 1024, the
// Cornell box's 1024 giving the 1e-9 they had). Radiosity's rays start off a polygon
// by 1e-7 of that polygon's own size (form_factors.cpp, direct_light.cpp,
// direct_display.cpp), the hemicube's near plane is 1e-9 of the receivers' size
// (item_buffer.cpp): relative already, they need no scene scale.
double scene_scale(const Scene& scene);

// The path tracer's and the two-pass eye pass's floor: 1e-9 of scale / 1024, the
// 1e-9 scene units they were tuned with on the Cornell box (scale 1024).
inline double offset_floor(double scale) { return 1e-9 * scale / 1024; }

}  // namespace gi
