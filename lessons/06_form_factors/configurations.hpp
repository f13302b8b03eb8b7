#pragma once
// Lesson 06: what every table is built from -- rectangles, a case with its exact form
// factor, and one method's F with its time (configurations.cpp).
#include <string>
#include <utility>
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"

namespace lesson06 {

using gi::FormFactorMethod;
using gi::vec3;

// A w x h rectangle centred at `centre`, spanned by unit vectors u and v, facing u x v.
gi::Polygon rectangle(vec3 centre, vec3 u, vec3 v, double w, double h);

// Two unit squares facing each other at distance d (sender first, facing up).
std::vector<gi::Polygon> facing_squares(double d);

// A configuration with its exact F from polygons[0] to polygons[1].
struct Case {
  std::string name;
  std::vector<gi::Polygon> polygons;  // F from polygons[0] to polygons[1]
  double exact;
  std::string source;  // where the exact value comes from
};

// F from polygons[0] to polygons[1] by `settings`, and its time in microseconds
// (median of at least three runs, and of enough runs to fill 20 ms).
// `row` picks the random stream of a Monte Carlo estimate; `runs` is the least
// number of timed runs.
std::pair<double, double> evaluate(const gi::FormFactorScene& scene, const gi::FormFactorSettings& settings,
                                   int row = 0, std::size_t runs = 3);

// `base` with its method set to `method`.
gi::FormFactorSettings with(FormFactorMethod method, const gi::FormFactorSettings& base);

// The four methods, in the order of every table.
inline constexpr FormFactorMethod methods[] = {FormFactorMethod::Differential, FormFactorMethod::Analytic,
                                               FormFactorMethod::MonteCarlo, FormFactorMethod::Hemicube};

}  // namespace lesson06
