#pragma once
#include <string>

#include "gi/core/math.hpp"

namespace gi {

// The Whitted/Phong material of the lecture:
//   I = k_a I_a + sum_lights S_l I_l [k_d (N.L) + k_s (R.V)^n] + k_r I_r + k_t I_t
// Colours are linear RGB in [0, 1].
struct Material {
  std::string name;
  Color diffuse{0.8};     // k_d times the surface colour
  double ambient = 0.0;   // k_a: the fraction of the scene's ambient light I_a reflected (times k_d's colour)
  Color specular{0.0};    // k_s: Phong highlight colour
  double shininess = 1;   // n: Phong exponent; larger is a smaller, sharper highlight
  Color mirror{0.0};      // k_r of an opaque reflector (metal, mirror): spawns a reflected ray
  Color transmission{0.0};  // filter of a dielectric (glass): non-zero spawns Fresnel-weighted
                            // reflected and transmitted rays
  double ior = 1.0;       // index of refraction of a dielectric (glass ~1.5, water 1.33)
  Color emission{0.0};    // light the surface gives off itself (area lights, radiosity)

  // Checkerboard texture in the x-z plane: squares of side `checker_size` alternate
  // `diffuse` and `checker_diffuse`. 0 turns it off.
  double checker_size = 0;
  Color checker_diffuse{0.0};

  bool is_dielectric() const { return max_component(transmission) > 0; }
};

// k_d at a point, after the checkerboard texture.
Color diffuse_at(const Material& material, const vec3& point);

}  // namespace gi
