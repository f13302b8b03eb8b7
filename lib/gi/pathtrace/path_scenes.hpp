#pragma once
#include <string>
#include <vector>

#include "gi/scene/scene.hpp"

namespace gi {

// The scenes the path tracer renders, by name:
//   cornell          the Cornell box exactly as radiosity solves it (gi/scene/cornell_box.hpp):
//                    the same quadrilaterals, reflectances and light (L = E / pi), all
//                    Lambertian, through the published camera
//   cornell-spheres  the box with a mirror sphere and a glass sphere instead of the blocks
//   furnace          a closed unit box, every wall rho = 0.5 and emitting L_e = 1, the camera
//                    inside: the radiance is L_e / (1 - rho) = 2 everywhere
//   whitted, spheres, s10, aliasing, soft
//                    the ray-tracing lessons' scenes, made physical (physical_scene below)
std::vector<std::string> path_scene_names();
Scene make_path_scene_by_name(const std::string& name);  // throws std::invalid_argument, listing the names

// The white furnace: the closed box [0, 1]^3, its six faces turned inwards, each with
// reflectance rho and emitted radiance L_e, the camera at the centre. Every surface
// point sees only other walls, so L = L_e + rho L everywhere, and
//   L = L_e / (1 - rho) = E / (pi (1 - rho)),
// or, with paths of at most D bounces, L_e (1 + rho + ... + rho^D).
Scene furnace_scene(double rho, double emitted_radiance);

// A Whitted scene made physical, for the path tracer:
//  - a point light of intensity I_l becomes a small emitting sphere (radius 2% of its
//    distance d to the camera's look-at point) of radiance L = I_l d^2 / r^2: seen from
//    the look-at point it then lights a diffuse surface as brightly as lesson 02's light,
//    which has no fall-off, does (k_d I_l against (rho / pi) L pi r^2 / d^2);
//  - an area light (lesson 04) becomes an emitting quad, L = pi I_l d^2 / A by the
//    same rule; an emitting quad of its shape (what the camera saw of it) is reused;
//  - the ambient term is dropped: the path tracer computes the light it stood for;
//  - materials keep their colours: see bsdf_at for which BSDF each becomes; the sky
//    (background) lights the scene too.
Scene physical_scene(const Scene& whitted);

}  // namespace gi
