#pragma once
// Lesson 12, step 2: where the solvers crawl or fail, and the spectral radius of RF
// that says how fast they go (stability.cpp).
#include "gi/radiosity/system/radiosity_system.hpp"
#include "gi/report/lesson.hpp"

namespace lesson12 {

// The stability table: the Cornell box closed and with its front open (`closed`,
// `open`), the empty closed box (`empty`) with reflectances near 1, and two systems
// past the physical (rho > 1, rows of F summing past 1); for each, rho(RF) and the
// iterations Jacobi and Gauss-Seidel take to ||r|| < 1e-6, or the failure detected.
void stability(const gi::RadiositySystem& closed, const gi::RadiositySystem& open,
               const gi::RadiositySystem& empty, int threads, gi::Lesson& lesson);

}  // namespace lesson12
