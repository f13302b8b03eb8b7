#include "gi/radiosity/form_factors/quadrature.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "gi/core/math.hpp"

namespace gi {

namespace {

// Nodes and weights of the n-point rule on [0, 1], by Newton's method on the
// Legendre polynomial P_n from the usual cosine guesses.
GaussRule make_gauss_legendre(int n) {
  GaussRule rule{std::vector<double>(n), std::vector<double>(n)};
  for (int i = 0; i < n; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), derivative = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = z;  // P_0, P_1, then the recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      derivative = n * (z * p1 - p0) / (z * z - 1);
      const double step = p1 / derivative;
      z -= step;
      if (std::abs(step) < 1e-15) break;
    }
    rule.nodes[i] = 0.5 * (1 - z);
    rule.weights[i] = 1.0 / ((1 - z * z) * derivative * derivative);  // 2 / (...) on [-1, 1], halved on [0, 1]
  }
  return rule;
}

// The 7-point Gauss and 15-point Kronrod rules on [-1, 1]: the Kronrod nodes
// interleave the Gauss ones (x_1, x_3, x_5 are Gauss nodes), x_7 = 0 is shared.
constexpr std::array<wide, 8> kronrod_x = {0.991455371120812639206854697526329L, 0.949107912342758524526189684047851L,
                                             0.864864423359769072789712788640926L, 0.741531185599394439863864773280788L,
                                             0.586087235467691130294144845693013L, 0.405845151377397166906606412076961L,
                                             0.207784955007898467600689403773245L, wide(0)};
constexpr std::array<wide, 8> kronrod_w = {0.022935322010529224963732008058970L, 0.063092092629978553290700663189204L,
                                             0.104790010322250183839876322541518L, 0.140653259715525918745189590510238L,
                                             0.169004726639267902826583426598550L, 0.190350578064785409913256402421014L,
                                             0.204432940075298892414161999234649L, 0.209482141084727828012999174891714L};
constexpr std::array<wide, 4> gauss_w = {0.129484966168869693270611432679082L, 0.279705391489276667901467771423780L,
                                           0.381830050505118944950369775488975L, 0.417959183673469387755102040816327L};

struct Interval {
  int piece;
  wide a, b, value, error;
  bool operator<(const Interval& other) const { return error < other.error; }  // a max-heap on the error
};

Interval kronrod(const std::function<wide(wide)>& f, int piece, wide a, wide b) {
  const wide centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const wide f0 = f(centre);
  wide k = kronrod_w[7] * f0, g = gauss_w[3] * f0;
  for (int j = 0; j < 7; ++j) {
    const wide both = f(centre - half * kronrod_x[j]) + f(centre + half * kronrod_x[j]);
    k += kronrod_w[j] * both;
    if (j % 2 == 1) g += gauss_w[j / 2] * both;
  }
  return {piece, a, b, k * half, std::abs((k - g) * half)};
}

}  // namespace

const GaussRule& gauss_legendre(int order) {
  if (order < 1 || order > 64) throw std::invalid_argument("Gauss-Legendre: the order must lie in [1, 64]");
  static const std::vector<GaussRule> rules = [] {
    std::vector<GaussRule> r(65);
    for (int n = 1; n <= 64; ++n) r[n] = make_gauss_legendre(n);
    return r;
  }();
  return rules[order];
}

Estimate integrate_adaptive(const std::vector<Integrand>& pieces, double relative_tolerance, int max_evaluations) {
  std::priority_queue<Interval> heap;
  std::vector<Interval> finished;  // too short to halve
  wide value = 0, error = 0;
  wide magnitude = 0;  // the sum of |interval values|: what round-off is relative to
  const auto take = [&](const Interval& interval, wide sign) {
    value += sign * interval.value;
    error += sign * interval.error;
    magnitude += sign * std::abs(interval.value);
  };
  const auto round_off = [&] { return 64 * std::numeric_limits<wide>::epsilon() * magnitude; };
  int evaluations = 0;
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    if (!(pieces[p].b > pieces[p].a)) continue;
    const Interval whole = kronrod(pieces[p].f, p, pieces[p].a, pieces[p].b);
    take(whole, 1);
    heap.push(whole);
    evaluations += 15;
  }
  while (!heap.empty() && error > std::max(relative_tolerance * std::abs(value), round_off()) &&
         evaluations + 30 <= max_evaluations) {
    const Interval worst = heap.top();
    heap.pop();
    const wide middle = 0.5 * (worst.a + worst.b);
    if (!(middle > worst.a && middle < worst.b)) {
      finished.push_back(worst);
      continue;
    }
    take(worst, -1);
    for (const Interval& half : {kronrod(pieces[worst.piece].f, worst.piece, worst.a, middle),
                                 kronrod(pieces[worst.piece].f, worst.piece, middle, worst.b)}) {
      take(half, 1);
      heap.push(half);
    }
    evaluations += 30;
  }
  // Added again from the intervals, so that the running sums' drift does not count.
  for (; !heap.empty(); heap.pop()) finished.push_back(heap.top());
  wide total = 0, total_error = 0;
  for (const Interval& interval : finished) total += interval.value, total_error += interval.error;
  return {static_cast<double>(total), static_cast<double>(std::max(total_error, round_off())), evaluations};
}

}  // namespace gi
