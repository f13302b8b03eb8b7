#pragma once
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/radiosity_system.hpp"

namespace gi {

// Exact direct light: what each element receives straight from the lights, by
// ray-cast form factors from the receiver (Wallace, Elmquist and Haines 1989), not
// by a hemicube. At a receiver point x with normal n, the irradiance from the lights
// is
//   H(x) = sum over lights l of  E_l F(x -> l) V(x, l)
// F(x -> l) is Lambert's contour integral over the light's outline (exact,
// form_factor_point_to_polygon). V(x, l) in [0, 1] is the light's visible fraction,
// as lesson 04's soft shadows measure it: the light is cut into cells x cells
// strata, one shadow ray goes to each stratum's centre, and each stratum counts
// with its own share of the form factor, cos_x cos_c A_c / (pi r^2):
//   V(x, l) = sum_c f_c v_c / sum_c f_c,   v_c = 1 if the ray to cell c is clear.
// Exact wherever the light is wholly seen or wholly hidden; in a penumbra the error
// shrinks as the cells do. The element's direct radiosity is the mean over its area,
// by an n x n Gauss-Legendre rule on its bilinear map:
//   D_i = rho_i (1 / A_i) integral over A_i of H(x) dx ~ rho_i sum_q w_q H(x_q)
// This is the first step E -> B of the solution, done exactly; only the light that
// has been reflected at least once is left to the hemicube (indirect_system).
struct DirectLightSettings {
  int light_cells = 8;      // each light cut into cells x cells strata for the shadow rays (1..64)
  int receiver_points = 2;  // n x n Gauss-Legendre points per element (1..8)
};
void check(const DirectLightSettings& settings);  // throws std::invalid_argument

// The lights of a mesh (its surfaces with emission E > 0), each cut into strata, ready
// to give H(x) at any point: per element here, per pixel in direct_display.hpp.
class DirectLighting {
 public:
  DirectLighting(const Mesh& mesh, int light_cells);  // throws std::invalid_argument outside 1..64
  // H(x) at point x with unit normal n; `scene` casts the shadow rays.
  Color irradiance(const FormFactorScene& scene, const vec3& x, const vec3& n) const;

 private:
  struct Cell {
    vec3 centre;
    double area;
  };
  struct Light {
    Polygon shape;
    Color exitance;  // E
    std::vector<Cell> cells;
  };
  double visible_fraction(const FormFactorScene& scene, const vec3& x, const vec3& n, const Light& light) const;
  std::vector<Light> lights_;
};

// D_i for every element of `mesh` (lights are the surfaces with emission E > 0), on
// `threads` threads (0 = all cores): the same for any number. `scene` must be built
// from element_shapes(mesh): it casts the shadow rays.
std::vector<Color> direct_radiosity(const FormFactorScene& scene, const Mesh& mesh,
                                    const DirectLightSettings& settings, int threads);

// D of one polygon of reflectance rho, at points x points (1..8): what the function
// above does for each element, here for any piece of a surface (hierarchical
// radiosity's leaves). `scene` casts the shadow rays.
Color direct_radiosity(const DirectLighting& lights, const FormFactorScene& scene, const Polygon& polygon,
                       const Color& rho, int points);

// What is left once the direct light D is known. Split B = E + B'; then
//   B' = D + R F B'      (the light reflected once, exactly, plus all later bounces)
// which is the radiosity equation with D in place of E: any solver of lesson 08-11
// solves it. `system` is the whole scene's system; its emission is replaced by D.
RadiositySystem indirect_system(RadiositySystem system, const std::vector<Color>& D);

// B = E + B': the full radiosity from the solution B' of indirect_system.
std::vector<Color> with_emission(const RadiositySystem& system, std::vector<Color> B_indirect);

}  // namespace gi
