#pragma once
// Lesson 14, step 1: Monte Carlo before it renders anything (monte_carlo.cpp).
#include "converge.hpp"
#include "gi/report/lesson.hpp"

namespace lesson14 {

// 1. Monte Carlo before it renders anything. RMS error of 400 estimates at each N of
//    int_0^pi sin x dx = 2 (uniform x), and of the irradiance under a sky of radiance
//    L(theta) = 1 + 3 cos^2(theta), E = int L cos dw = 2.5 pi, drawing directions
//    uniformly (p = 1 / 2 pi) or by the cosine (p = cos / pi).
void monte_carlo_warm_up(const Settings& s, gi::Lesson& lesson);

}  // namespace lesson14
