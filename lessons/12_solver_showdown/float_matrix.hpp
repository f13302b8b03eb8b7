#pragma once
// Lesson 12, steps 3 and 5: Gauss-Seidel on a float matrix -- where its residual stops
// falling, against double, and how close one sweep comes to the memory's speed
// (float_matrix.cpp; the float sweep itself is gi/radiosity/system/float_sweep.hpp).
#include "gi/radiosity/system/radiosity_system.hpp"
#include "gi/report/lesson.hpp"

namespace lesson12 {

// The precision table: 30 Gauss-Seidel sweeps of `system` in float and in double, the
// relative residual ||r|| / ||E|| of each every third sweep.
void precision(const gi::RadiositySystem& system, gi::Lesson& lesson);

// The bandwidth table: one sweep over a dense random n x n float matrix (rows summing
// to about 1) against the time to just read it, one thread, median of 3.
void bandwidth(int n, gi::Lesson& lesson);

}  // namespace lesson12
