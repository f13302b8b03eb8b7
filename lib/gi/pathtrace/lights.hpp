#pragma once
#include <vector>

#include "gi/core/sampling.hpp"
#include "gi/scene/scene.hpp"

namespace gi {

// The path tracer's lights are surfaces that emit: every triangle, quad (parallelogram)
// or sphere whose material has an emission. Emission is radiance L_e, the same in every
// direction (a Lambertian emitter, L = E / pi), from the front of a triangle or quad
// (the side its normal points to) and from the outside of a sphere.
//
// Next-event estimation picks a point y on a light, with a density in area measure:
//   1. a light k, with probability P_k proportional to its power pi A_k lum(L_e,k),
//      so that bright large lights get the samples;
//   2. a point uniformly over the light's area, p = 1 / A_k; for a sphere seen from
//      outside, uniformly over the cap that x can see, p = 1 / A_cap(x) (the far side
//      only ever faces away: sampling it would waste the sample).
// So p_A(y) = P_k / A_k (or P_k / A_cap(x)). The integrator converts it to solid angle
// (area_to_solid_angle) to weigh it against BSDF sampling.
struct Light {
  enum class Shape { Triangle, Quad, Sphere };
  Shape shape;
  int index;       // in the scene's vector of that shape
  Color radiance;  // L_e
  double area;
};

struct Lights {
  std::vector<Light> lights;
  DiscreteDistribution choice;   // P_k; empty when there are no lights
  std::vector<int> of_material;  // the light whose surface has this material, or -1
};

// The scene's emitters. Gives each emitter a material of its own (a copy), so that a
// ray that hits a light knows which light from hit.material alone. Throws
// std::invalid_argument for an emitting plane (infinite power) or a negative emission.
Lights find_lights(Scene& scene);

struct LightSample {
  vec3 point;       // y
  vec3 normal;      // the light's unit normal at y, on its emitting side
  Color radiance;   // L_e(y)
  double pdf_area;  // p_A(y), choice of the light included
  int light;
};

// A point on a light for the shading point x: u_choice picks the light, u the point.
// Requires at least one light.
LightSample sample_light(const Lights& lights, const Scene& scene, const vec3& x, double u_choice, vec2 u);

// p_A(y) of the points y of light k that x can see, as sample_light makes them from x:
// the same at every such point, since each light is sampled uniformly (over its area,
// or over the cap of a sphere that x sees).
double light_pdf_area(const Lights& lights, const Scene& scene, int k, const vec3& x);

}  // namespace gi
