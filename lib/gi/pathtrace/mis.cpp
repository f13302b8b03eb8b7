#include "gi/pathtrace/mis.hpp"

#include <stdexcept>

#include "gi/core/not_implemented.hpp"
#include "gi/core/sampling.hpp"

namespace gi {

namespace {
const char* const strategy_names_[] = {"bsdf", "lights", "mis"};
}

std::string name(Strategy strategy) { return strategy_names_[static_cast<int>(strategy)]; }

std::vector<std::string> strategy_names() { return {std::begin(strategy_names_), std::end(strategy_names_)}; }

Strategy strategy_from_name(const std::string& text) {
  for (int i = 0; i < 3; ++i)
    if (text == strategy_names_[i]) return static_cast<Strategy>(i);
  throw std::invalid_argument("unknown strategy '" + text + "' (bsdf, lights, mis)");
}

double light_sample_weight(Strategy strategy, double p_light, double p_bsdf) {
  switch (strategy) {
    case Strategy::Bsdf: return 0.0;
    case Strategy::Lights: return 1.0;
    case Strategy::Mis: return power_heuristic(1, p_light, 1, p_bsdf);
  }
  return 0.0;
}

double bsdf_sample_weight(Strategy strategy, double p_bsdf, double p_light) {
  // Under Lights the light sample already carried this light path: counting it
  // again here would double the direct light.
  // BEGIN EXERCISE 14.6 the weight of emission found by BSDF sampling
  switch (strategy) {
    case Strategy::Bsdf: return 1.0;
    case Strategy::Lights: return 0.0;
    case Strategy::Mis: return power_heuristic(1, p_bsdf, 1, p_light);
  }
  return 0.0;
  // END EXERCISE 14.6
}

}  // namespace gi
