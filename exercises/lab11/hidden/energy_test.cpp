// Hidden graded tests of lab 11 (the autograder's): a shot keeps the books on energy.
// One point per test.
#include <gtest/gtest.h>

#include "gi/core/rng.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "support/print.hpp"

using gi::Color;

TEST(Ex11_1_Energy, WhatArrivesIsWhatLeftTimesTheFormFactors) {
  // Power leaving the patch towards element j: A_p dB_p F_pj. Arriving there and
  // reflected: A_j dB_j = rho_j A_p dB_p F_pj. So sum_j A_j dB_j / rho_j = A_p dB_p sum_j F_pj.
  gi::Rng rng(1111);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 6;
    std::vector<double> area, F_p(n);
    std::vector<Color> rho, B, unshot;
    for (int j = 0; j < n; ++j) {
      area.push_back(0.5 + rng.uniform());
      rho.push_back(Color(0.1 + 0.8 * rng.uniform(), 0.1 + 0.8 * rng.uniform(), 0.1 + 0.8 * rng.uniform()));
      unshot.push_back(Color(rng.uniform(), rng.uniform(), rng.uniform()));
      B.push_back(unshot.back() + Color(rng.uniform()));
      F_p[j] = j < 2 ? 0.0 : 0.2 * rng.uniform();  // the patch is elements 0 and 1
    }
    const gi::Patch patch{gi::Polygon{{}, {}, {}, area[0] + area[1]}, 0, 0, 2};
    const Color leaving = unshot[0] * area[0] + unshot[1] * area[1];
    double f_sum = 0;
    for (double f : F_p) f_sum += f;
    const std::vector<Color> before = unshot;
    gi::shoot(patch, F_p, area, rho, B, unshot);
    Color arrived(0.0);
    for (int j = 2; j < n; ++j) arrived += area[j] * (unshot[j] - before[j]) / rho[j];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(arrived[c], leaving[c] * f_sum, 1e-12) << "trial " << trial << ", channel " << c
                                                          << ": the power received must be the power shot times sum_j F_pj";
  }
}
