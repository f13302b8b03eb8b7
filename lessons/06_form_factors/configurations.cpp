// Lesson 06: rectangles and one method's F with its time (configurations.hpp).
#include "configurations.hpp"

#include "gi/core/timer.hpp"

namespace lesson06 {

gi::Polygon rectangle(vec3 centre, vec3 u, vec3 v, double w, double h) {
  const vec3 c0 = centre - 0.5 * w * u - 0.5 * h * v;
  return gi::make_polygon({c0, c0 + w * u, c0 + w * u + h * v, c0 + h * v});
}

// Two unit squares facing each other at distance d (sender first, facing up).
std::vector<gi::Polygon> facing_squares(double d) {
  return {rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1), rectangle({0, d, 0}, {1, 0, 0}, {0, 0, 1}, 1, 1)};
}

std::pair<double, double> evaluate(const gi::FormFactorScene& scene, const gi::FormFactorSettings& settings,
                                   int row, std::size_t runs) {
  std::vector<double> times;
  double value = 0, total = 0;
  while (times.size() < runs || (total < 0.02 && times.size() < 1000)) {
    const gi::Timer timer;
    value = gi::form_factor_row(scene, scene.polygons()[0], row, settings)[1];
    times.push_back(timer.seconds());
    total += times.back();
  }
  return {value, 1e6 * gi::median(times)};
}

gi::FormFactorSettings with(FormFactorMethod method, const gi::FormFactorSettings& base) {
  gi::FormFactorSettings s = base;
  s.method = method;
  return s;
}

}  // namespace lesson06
