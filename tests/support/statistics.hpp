#pragma once
// Statistics for the tests of random code.
//
// Pearson's chi-square test of samples against the density they should follow, for
// the tests of every sampler (unit tests and graded labs alike), as pbrt's
// bsdfs_test.cpp and Nori's chi2test.cpp do it: bin the samples into cells, integrate
// the density over the same cells for the counts expected, pool the cells that expect
// fewer than 5 (the chi-square approximation needs about 5 per cell), and ask how
// likely a statistic this large is if the samples do follow the density.
#include <functional>
#include <vector>

#include "gi/core/math.hpp"

namespace gi::testing {

struct ChiSquare {
  double statistic = 0;
  int degrees_of_freedom = 0;
  double p_value = 1;  // P(a correct sampler gives a statistic this large or larger); 0 if a
                       // sample fell where the density is 0
};

// observed[i] and expected[i] are the counts of cell i; the expected counts must add up
// to the number of samples.
ChiSquare chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected);

// Per-test significance that keeps the chance of any false failure among `tests`
// independent tests at `family` (Sidak): 1 - (1 - family)^(1 / tests).
double sidak_significance(double family, int tests);

// P(X >= x) for X chi-square distributed with k degrees of freedom: the regularised
// upper incomplete gamma function Q(k / 2, x / 2).
double chi_square_p_value(double x, int k);

// Counts of points in an nx x ny grid of cells over the rectangle [lo, hi]; points
// outside it are counted in an extra last cell (which expects 0).
std::vector<double> histogram_2d(const std::vector<vec2>& points, vec2 lo, vec2 hi, int nx, int ny);

// Expected counts of `samples` points of a density over the same cells (plus the empty
// extra cell): the density integrated over each cell by Simpson's rule on a
// `sub` x `sub` grid per cell (sub even; exact for cubics, so put cell borders where
// the density has a kink or a jump: it is read from inside each cell).
std::vector<double> expected_2d(const std::function<double(vec2)>& density, vec2 lo, vec2 hi, int nx, int ny,
                                double samples, int sub = 8);

// Directions as points of the rectangle [-1, 1] x [0, 2 pi) of (z, phi) = (cos theta,
// azimuth): equal areas there are equal solid angles (dw = dz dphi), so a density per
// steradian is a density in (z, phi) as it stands.
vec2 direction_to_z_phi(const vec3& w);
vec3 z_phi_to_direction(vec2 z_phi);

// The integral over the sphere of a function of direction (a density's, to check it is
// 1), by the midpoint rule on nz x nphi cells of (z, phi).
double integral_over_sphere(const std::function<double(const vec3&)>& g, int nz = 400, int nphi = 800);

// The mean of n independent estimates and its standard error sqrt(s^2 / n): a test
// then asks whether a known answer lies within a few standard errors (a t-test; with
// n >= 20 estimates, 4.5 standard errors are exceeded by chance about once in 10^4
// runs, 5 about once in 2 * 10^4... see each test's comment).
struct Estimate {
  double mean = 0;
  double standard_error = 0;
};
Estimate estimate(const std::vector<double>& values);

}  // namespace gi::testing
