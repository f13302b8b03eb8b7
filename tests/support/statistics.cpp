#include "support/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::testing {

namespace {

// P(a, x) by its power series, for x < a + 1:
//   P = e^-x x^a / Gamma(a + 1) * sum_n x^n / ((a + 1) ... (a + n)).
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by its continued fraction (modified Lentz), for x >= a + 1.
double gamma_q_fraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    d = std::abs(d) < tiny ? tiny : d;
    c = b + an / c;
    c = std::abs(c) < tiny ? tiny : c;
    d = 1 / d;
    h *= d * c;
    if (std::abs(d * c - 1) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chi_square_p_value(double x, int k) {
  if (k <= 0) return 1.0;
  if (!(x > 0)) return 1.0;
  const double a = 0.5 * k, half = 0.5 * x;
  return half < a + 1 ? 1 - gamma_p_series(a, half) : gamma_q_fraction(a, half);
}

double sidak_significance(double family, int tests) { return 1 - std::pow(1 - family, 1.0 / tests); }

ChiSquare chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquare result;
  std::vector<std::pair<double, double>> cells;  // (observed, expected) of the cells kept
  double pooled_observed = 0, pooled_expected = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] <= 0) {
      if (observed[i] > 0) return {std::numeric_limits<double>::infinity(), 0, 0.0};  // a sample where none can be
      continue;
    }
    if (expected[i] < 5) {
      pooled_observed += observed[i], pooled_expected += expected[i];
    } else {
      cells.push_back({observed[i], expected[i]});
    }
  }
  if (pooled_expected >= 5 || cells.empty()) {
    if (pooled_expected > 0) cells.push_back({pooled_observed, pooled_expected});
  } else if (pooled_expected > 0) {
    // Too little for a cell of its own: joins the cell that expects the least.
    auto& smallest =
        *std::min_element(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    smallest.first += pooled_observed, smallest.second += pooled_expected;
  }
  for (const auto& [o, e] : cells) result.statistic += (o - e) * (o - e) / e;
  result.degrees_of_freedom = static_cast<int>(cells.size()) - 1;
  result.p_value = chi_square_p_value(result.statistic, result.degrees_of_freedom);
  return result;
}

std::vector<double> histogram_2d(const std::vector<vec2>& points, vec2 lo, vec2 hi, int nx, int ny) {
  std::vector<double> counts(static_cast<std::size_t>(nx) * ny + 1, 0.0);
  for (const vec2& p : points) {
    const vec2 t = (p - lo) / (hi - lo);
    if (!(t.x >= 0 && t.x <= 1 && t.y >= 0 && t.y <= 1)) {
      counts.back() += 1;
      continue;
    }
    const int i = std::min(nx - 1, static_cast<int>(t.x * nx)), j = std::min(ny - 1, static_cast<int>(t.y * ny));
    counts[static_cast<std::size_t>(j) * nx + i] += 1;
  }
  return counts;
}

std::vector<double> expected_2d(const std::function<double(vec2)>& density, vec2 lo, vec2 hi, int nx, int ny,
                                double samples, int sub) {
  std::vector<double> counts(static_cast<std::size_t>(nx) * ny + 1, 0.0);
  const vec2 cell = (hi - lo) / vec2(nx, ny), h = cell / double(sub);
  // Points a hair inside the cell: at a border the density's value from this side, so
  // that a jump on a border (the horizon, a cone's rim) is integrated exactly.
  const vec2 inset = 1e-9 * cell, span = cell - 2.0 * inset;
  const auto weight = [sub](int k) { return k == 0 || k == sub ? 1.0 : (k % 2 ? 4.0 : 2.0); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double integral = 0;
      for (int b = 0; b <= sub; ++b)
        for (int a = 0; a <= sub; ++a)
          integral += weight(a) * weight(b) * density(lo + cell * vec2(i, j) + inset + span * vec2(a, b) / double(sub));
      counts[static_cast<std::size_t>(j) * nx + i] = samples * integral * h.x * h.y / 9;
    }
  return counts;
}

vec2 direction_to_z_phi(const vec3& w) {
  const double phi = std::atan2(w.y, w.x);
  return {std::clamp(w.z, -1.0, 1.0), phi < 0 ? phi + 2 * pi : phi};
}

vec3 z_phi_to_direction(vec2 z_phi) {
  const double r = std::sqrt(std::max(0.0, 1 - z_phi.x * z_phi.x));
  return {r * std::cos(z_phi.y), r * std::sin(z_phi.y), z_phi.x};
}

double integral_over_sphere(const std::function<double(const vec3&)>& g, int nz, int nphi) {
  double sum = 0;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) sum += g(z_phi_to_direction({-1 + (i + 0.5) * 2.0 / nz, (j + 0.5) * 2 * pi / nphi}));
  return sum * (2.0 / nz) * (2 * pi / nphi);
}

Estimate estimate(const std::vector<double>& values) {
  const double n = double(values.size());
  double sum = 0, sum2 = 0;
  for (double v : values) sum += v;
  const double mean = sum / n;
  for (double v : values) sum2 += (v - mean) * (v - mean);
  return {mean, values.size() > 1 ? std::sqrt(sum2 / (n - 1) / n) : 0.0};
}

}  // namespace gi::testing
