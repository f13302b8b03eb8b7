// Small radiosity systems the lab's tests share.
#pragma once
#include "gi/radiosity/solvers.hpp"

namespace lab09 {

// Three elements, F not symmetric, reflectances per channel: every mistake changes
// the answer.
inline gi::RadiositySystem three() {
  gi::RadiositySystem s;
  s.area = {1.0, 2.0, 0.5};
  s.rho = {gi::Color(0.5, 0.4, 0.3), gi::Color(0.8), gi::Color(0.2, 0.6, 0.9)};
  s.emission = {gi::Color(1.0), gi::Color(0.0), gi::Color(0.0, 0.5, 0.0)};
  s.F = {3, {0.0, 0.5, 0.2,  //
             0.25, 0.0, 0.1,  //
             0.4, 0.4, 0.0}};
  return s;
}

// Uniform reflectance above 1: more light leaves every surface than arrives.
inline gi::RadiositySystem runaway() {
  gi::RadiositySystem s;
  s.area = {1, 1, 1};
  s.rho = {gi::Color(1.4), gi::Color(1.4), gi::Color(1.4)};
  s.emission = {gi::Color(1), gi::Color(0), gi::Color(0)};
  s.F = {3, {0, 0.5, 0.5, 0.5, 0, 0.5, 0.5, 0.5, 0}};
  return s;
}

}  // namespace lab09
