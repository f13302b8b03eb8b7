#include "gi/radiosity/form_factors/configuration_factors.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gi/radiosity/form_factors/quadrature.hpp"

namespace gi {

namespace {

constexpr double pi = std::numbers::pi;

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("configuration factor: ") + what);
}

void require_positive(std::initializer_list<double> lengths) {
  for (double x : lengths) require(x > 0 && std::isfinite(x), "every length must be positive and finite");
}

void require_finite(std::initializer_list<double> coordinates) {
  for (double x : coordinates) require(std::isfinite(x), "every coordinate must be finite");
}

// The directly opposed rectangles' series (see the header), for x^2 + y^2 <= 1/4:
// its terms shrink at least 4-fold each, so 30 of them leave 1e-17.
double parallel_series(double x, double y) {
  constexpr int terms = 40;
  std::array<double, terms> mx{}, my{};
  for (int m = 0; m < terms; ++m) {
    mx[m] = 2 * std::pow(x, 2 * m) / ((2 * m + 1.0) * (2 * m + 2.0));
    my[m] = 2 * std::pow(y, 2 * m) / ((2 * m + 1.0) * (2 * m + 2.0));
  }
  double sum = 0;
  for (int k = 0; k < terms; ++k) {
    double inner = 0, binomial = 1;  // C(k, m), built up along m
    for (int m = 0; m <= k; ++m) {
      inner += binomial * mx[m] * my[k - m];
      binomial = binomial * (k - m) / (m + 1);
    }
    const double term = (k + 1) * (k % 2 ? -inner : inner);
    sum += term;
    if (std::abs(term) <= 1e-17 * std::abs(sum)) break;
  }
  return x * y / pi * sum;
}

// x atan(1/x), and g(root) - g(big) for root = sqrt(big^2 + small^2) without
// subtracting the two: root - big = small^2 / (root + big), and
// atan(1/root) - atan(1/big) = atan((big - root) / (root big + 1)).
double g(double x) { return x * std::atan(1 / x); }
double g_difference(double big, double small, double root) {
  const double gap = small * small / (root + big);
  return gap * std::atan(1 / root) - big * std::atan(gap / (root * big + 1));
}

// p ln(p (1 + s) / ((1 + p) s)) for s = p + q, the ratio written 1 - q / ((1 + p) s): log1p
// of that while it is small, else the ratio's factors apart (near 1 - that, q >> p,
// the subtraction 1 - q / (...) would leave only the rounding of q / (...)).
double log_term(double p, double q, double s) {
  const double x = q / ((1 + p) * s);
  return p * (x < 0.5 ? std::log1p(-x) : std::log(p / s) + std::log1p(q / (1 + p)));
}

// The integral over two boxes ([a0, a1] x [b0, b1] and [c0, c1] x [d0, d1]) of a
// kernel, by a Gauss-Legendre rule of `order` in each of the four coordinates. For
// rectangles whose centres are 2 sizes apart or more the kernel is smooth and
// positive there: order 12 is exact to round-off (1e-14) from 2 sizes, order 8 from
// 3 (both checked against the corner sum at 50 digits, over 600 random pairs of
// rectangles with sides from 0.1 to 1 at every angle and offset).
double integral_4d(const std::array<double, 8>& box, int order,
                   const std::function<double(double, double, double, double)>& f) {
  const GaussRule& rule = gauss_legendre(order);
  const auto at = [&](int axis, int i) { return box[2 * axis] + rule.nodes[i] * (box[2 * axis + 1] - box[2 * axis]); };
  wide sum = 0;
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j)
      for (int k = 0; k < order; ++k)
        for (int l = 0; l < order; ++l)
          sum += rule.weights[i] * rule.weights[j] * rule.weights[k] * rule.weights[l] *
                 f(at(0, i), at(1, j), at(2, k), at(3, l));
  double volume = 1;
  for (int axis = 0; axis < 4; ++axis) volume *= box[2 * axis + 1] - box[2 * axis];
  return static_cast<double>(sum) * volume;
}

// Howell's sixteen corner terms, sum (-1)^(i+j+k+l) G(i, j, k, l), in gi::wide, with
// the bound of their cancellation's round-off: each term carries a few units of
// round-off of itself, so the sum carries about eps * sum |G| (measured: never more
// than 2 eps sum |G| over random pairs of rectangles). Far apart the terms grow like
// distance^2 while the sum shrinks like 1 / distance^2.
struct CornerSum {
  wide value;
  wide round_off;
};
CornerSum corner_sum(const std::function<wide(int, int, int, int)>& G) {
  wide sum = 0, magnitude = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) {
          const wide term = G(i, j, k, l);
          sum += (i + j + k + l) % 2 ? -term : term;
          magnitude += std::abs(term);
        }
  return {sum, 4 * std::numeric_limits<wide>::epsilon() * magnitude};
}

// A_1 F_12 for offset rectangles, the four sides' intervals in `box` (the sender's
// two, then the receiver's two), chosen by how far apart the centres are in sizes
// (the larger diagonal):
//  - the corner sum (a few microseconds) while its round-off is below
//    `corner_accuracy` of its value: in double to about 2 sizes apart, in long double
//    to about 5 (never farther than 30);
//  - from 2 sizes, the Gauss rule (25 to 120 microseconds), exact to round-off there;
//  - nearer, the corner sum while its round-off is below `near_accuracy`, else (thin
//    rectangles: the terms grow with the length, the sum with the area) the sum over
//    the two halves of the longest side, each pair taken the same way (A_1 F_12 adds
//    up over the parts of either rectangle), 20 halvings deep at most.
// Measured in double against the corner sum at 50 digits over 1000 random pairs
// (sides 0.01 to 1, 0.05 to 40 sizes apart): within 2.5e-14 from 2 sizes apart and
// 2e-13 nearer, at 0.2 ms on average and 5 ms at most. In long double the corner sum
// keeps 1e-14 near by itself.
constexpr double corner_accuracy = 1e-14, near_accuracy = 1e-12;
constexpr double gauss_from = 2, gauss_order_8_from = 3, corner_until = 30;
constexpr int deepest_split = 20;
using Box = std::array<double, 8>;
struct OffsetRectangles {
  std::function<double(const Box&)> ratio;      // centres apart over size
  std::function<CornerSum(const Box&)> corners;  // 2 pi A_1 F_12 and its round-off
  std::function<double(double, double, double, double)> kernel;
};
double exchange(const OffsetRectangles& pair, const Box& box, int depth = 0) {
  const double ratio = pair.ratio(box);
  if (ratio < corner_until) {
    const CornerSum corners = pair.corners(box);
    const double accuracy = ratio < gauss_from ? near_accuracy : corner_accuracy;
    if (corners.round_off <= accuracy * std::abs(corners.value) || depth == deepest_split)
      return static_cast<double>(corners.value / (2 * pi_wide));
  }
  if (ratio >= gauss_from) return integral_4d(box, ratio >= gauss_order_8_from ? 8 : 12, pair.kernel);
  int longest = 0;
  for (int axis = 1; axis < 4; ++axis)
    if (box[2 * axis + 1] - box[2 * axis] > box[2 * longest + 1] - box[2 * longest]) longest = axis;
  Box low = box, high = box;
  low[2 * longest + 1] = high[2 * longest] = 0.5 * (box[2 * longest] + box[2 * longest + 1]);
  return exchange(pair, low, depth + 1) + exchange(pair, high, depth + 1);
}

}  // namespace

double ff_parallel_rectangles(double a, double b, double c) {
  require_positive({a, b, c});
  const double x = a / c, y = b / c;
  if (x * x + y * y <= 0.25) return parallel_series(x, y);
  const double x2 = 1 + x * x, y2 = 1 + y * y;
  return 2 / (pi * x * y) *
         (0.5 * std::log(x2 * y2 / (x2 + y * y)) + x * std::sqrt(y2) * std::atan(x / std::sqrt(y2)) +
          y * std::sqrt(x2) * std::atan(y / std::sqrt(x2)) - x * std::atan(x) - y * std::atan(y));
}

double ff_perpendicular_rectangles(double l, double w, double h) {
  require_positive({l, w, h});
  const double W = w / l, H = h / l;
  const double w2 = W * W, h2 = H * H, s = w2 + h2, root = std::sqrt(s);
  // W atan(1/W) + H atan(1/H) - sqrt(s) atan(1/sqrt(s)), the last two not subtracted directly.
  const double big = std::max(W, H), small = std::min(W, H);
  const double arctangents = g(small) - g_difference(big, small, root);
  // The textbook's logarithms of ratios near 1, as log1p of their small parts:
  // (1+w2)(1+h2)/(1+s) = 1 + w2 h2/(1+s), w2 (1+s)/((1+w2) s) = 1 - h2/((1+w2) s), and alike.
  const double logs = std::log1p(w2 * h2 / (1 + s)) + log_term(w2, h2, s) + log_term(h2, w2, s);
  return (arctangents + 0.25 * logs) / (pi * W);
}

double ff_point_to_parallel_rectangle_corner(double a, double b, double c) {
  require_positive({a, b, c});
  const double A = a / c, B = b / c;  // two positive terms: nothing cancels
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * pi);
}

double ff_point_to_perpendicular_rectangle_corner(double a, double b, double c) {
  require_positive({a, b, c});
  // atan(a/c) - (c/q) atan(a/q) with q = sqrt(b^2 + c^2), as
  // [atan(a/c) - atan(a/q)] + (1 - c/q) atan(a/q), each part without cancellation.
  const double q = std::hypot(b, c), q_minus_c = b * b / (q + c);
  return (std::atan(a * q_minus_c / (c * q + a * a)) + q_minus_c / q * std::atan(a / q)) / (2 * pi);
}

double ff_parallel_rectangles_offset(double x1, double x2, double y1, double y2, double xi1, double xi2, double eta1,
                                     double eta2, double z) {
  require_finite({x1, x2, y1, y2, xi1, xi2, eta1, eta2});
  require_positive({x2 - x1, y2 - y1, xi2 - xi1, eta2 - eta1, z});
  const OffsetRectangles pair{
      [z](const Box& b) {
        const double size = std::max(std::hypot(b[1] - b[0], b[3] - b[2]), std::hypot(b[5] - b[4], b[7] - b[6]));
        return std::hypot(0.5 * (b[0] + b[1] - b[4] - b[5]), 0.5 * (b[2] + b[3] - b[6] - b[7]), z) / size;
      },
      [z](const Box& b) {
        const std::array<wide, 2> x{b[0], b[1]}, y{b[2], b[3]}, xi{b[4], b[5]}, eta{b[6], b[7]};
        const wide zz = static_cast<wide>(z) * z;
        return corner_sum([&](int i, int j, int k, int l) {
          const wide u = x[i] - xi[k], v = y[j] - eta[l];
          const wide su = std::sqrt(v * v + zz), sv = std::sqrt(u * u + zz);
          return u * su * std::atan(u / su) + v * sv * std::atan(v / sv) - zz / 2 * std::log(u * u + v * v + zz);
        });
      },
      // F = 1/A_1 int int z^2 / (pi r^4): both cosines are z / r.
      [z](double x, double y, double xi, double eta) {
        const double r2 = (x - xi) * (x - xi) + (y - eta) * (y - eta) + z * z;
        return z * z / (pi * r2 * r2);
      }};
  return exchange(pair, {x1, x2, y1, y2, xi1, xi2, eta1, eta2}) / ((x2 - x1) * (y2 - y1));
}

double ff_perpendicular_rectangles_offset(double x1, double x2, double y1, double y2, double eta1, double eta2,
                                          double z1, double z2) {
  require_finite({x1, y1, y2, eta1, eta2, z1});
  require_positive({x2 - x1, y2 - y1, eta2 - eta1, z2 - z1});
  require(x1 >= 0 && z1 >= 0, "the rectangles must lie on their sides of the common line (x1 >= 0, z1 >= 0)");
  const OffsetRectangles pair{
      [](const Box& b) {
        const double size = std::max(std::hypot(b[1] - b[0], b[3] - b[2]), std::hypot(b[5] - b[4], b[7] - b[6]));
        return std::hypot(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3] - b[4] - b[5]), 0.5 * (b[6] + b[7])) / size;
      },
      [](const Box& b) {
        const std::array<wide, 2> x{b[0], b[1]}, y{b[2], b[3]}, eta{b[4], b[5]}, z{b[6], b[7]};
        return corner_sum([&](int i, int j, int k, int l) {
          const wide s2 = x[i] * x[i] + z[l] * z[l], s = std::sqrt(s2), d = y[j] - eta[k];
          // Both terms vanish in the limit s, d -> 0 (a shared edge): skip them there.
          const wide along = s > 0 ? d * s * std::atan(d / s) : wide(0);
          const wide logarithm = s2 + d * d > 0 ? (s2 - d * d) / 4 * std::log(s2 + d * d) : wide(0);
          return along - logarithm;
        });
      },
      // F = 1/A_1 int int x z / (pi r^4): cos_1 = z / r, cos_2 = x / r.
      [](double x, double y, double eta, double z) {
        const double r2 = x * x + (y - eta) * (y - eta) + z * z;
        return x * z / (pi * r2 * r2);
      }};
  return exchange(pair, {x1, x2, y1, y2, eta1, eta2, z1, z2}) / ((x2 - x1) * (y2 - y1));
}

}  // namespace gi
