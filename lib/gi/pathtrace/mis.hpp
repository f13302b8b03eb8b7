#pragma once
#include <string>
#include <vector>

namespace gi {

// Two ways to find the light that reaches a surface point x:
//   light sampling (next-event estimation): pick a point y on a light and cast a shadow
//     ray to it; the direction x -> y has density p_light (solid angle);
//   BSDF sampling: pick a direction by the BSDF, density p_bsdf, and see whether the
//     ray hits a light.
// Either alone is unbiased. Light sampling is good for small lights and rough
// surfaces; BSDF sampling for large lights and sharp lobes. Which the path tracer
// uses (as pbrt's SimplePathIntegrator, and Veach's combination):
//   Bsdf    BSDF sampling alone: a path counts the emission it runs into
//   Lights  light sampling for the direct light at every vertex; a BSDF ray that then
//           hits a light must add nothing, or that light is counted twice
//   Mis     both, each weighted by the power heuristic; the weights of one light path
//           found both ways add up to 1
// Emission seen by the camera or through a mirror or glass counts fully in every
// strategy: no light sample can find it (the integrator's explicit branch).
enum class Strategy { Bsdf, Lights, Mis };

std::string name(Strategy strategy);  // "bsdf", "lights", "mis"
std::vector<std::string> strategy_names();
Strategy strategy_from_name(const std::string& name);  // throws std::invalid_argument

// w_light: the weight of a light sample (next-event estimation). 0 under Bsdf, which
// takes no light samples.
double light_sample_weight(Strategy strategy, double p_light, double p_bsdf);

// w_bsdf: the weight of the emission a BSDF-sampled ray finds on a light, after a
// non-specular bounce.
double bsdf_sample_weight(Strategy strategy, double p_bsdf, double p_light);

}  // namespace gi
