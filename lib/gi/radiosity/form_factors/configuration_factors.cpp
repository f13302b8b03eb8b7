#include "gi/radiosity/form_factors/configuration_factors.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
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
// kernel, by a Gauss-Legendre rule of order 8 in each of the four coordinates: for
// rectangles 30 sizes apart the kernel is smooth and positive there, and the rule
// exact to round-off.
double integral_4d(const std::array<double, 8>& box, const std::function<double(double, double, double, double)>& f) {
  const GaussRule& rule = gauss_legendre(8);
  const auto at = [&](int axis, int i) { return box[2 * axis] + rule.nodes[i] * (box[2 * axis + 1] - box[2 * axis]); };
  long double sum = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k)
        for (int l = 0; l < 8; ++l)
          sum += rule.weights[i] * rule.weights[j] * rule.weights[k] * rule.weights[l] *
                 f(at(0, i), at(1, j), at(2, k), at(3, l));
  double volume = 1;
  for (int axis = 0; axis < 4; ++axis) volume *= box[2 * axis + 1] - box[2 * axis];
  return static_cast<double>(sum) * volume;
}

// Howell's sixteen corner terms, sum (-1)^(i+j+k+l) G(i, j, k, l), in long double.
long double corner_sum(const std::function<long double(int, int, int, int)>& G) {
  long double sum = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) sum += ((i + j + k + l) % 2 ? -1 : 1) * G(i, j, k, l);
  return sum;
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
  const double area = (x2 - x1) * (y2 - y1);
  const double size = std::max(std::hypot(x2 - x1, y2 - y1), std::hypot(xi2 - xi1, eta2 - eta1));
  const double centres = std::hypot(0.5 * (x1 + x2 - xi1 - xi2), 0.5 * (y1 + y2 - eta1 - eta2), z);
  if (centres > 30 * size) {
    // F = 1/A_1 int int z^2 / (pi r^4): both cosines are z / r.
    return integral_4d({x1, x2, y1, y2, xi1, xi2, eta1, eta2}, [z](double x, double y, double xi, double eta) {
             const double r2 = (x - xi) * (x - xi) + (y - eta) * (y - eta) + z * z;
             return z * z / (pi * r2 * r2);
           }) / area;
  }
  const std::array<long double, 2> x{x1, x2}, y{y1, y2}, xi{xi1, xi2}, eta{eta1, eta2};
  const long double zz = static_cast<long double>(z) * z;
  const long double sum = corner_sum([&](int i, int j, int k, int l) {
    const long double u = x[i] - xi[k], v = y[j] - eta[l];
    const long double su = std::sqrt(v * v + zz), sv = std::sqrt(u * u + zz);
    return u * su * std::atan(u / su) + v * sv * std::atan(v / sv) - zz / 2 * std::log(u * u + v * v + zz);
  });
  return static_cast<double>(sum / (2 * std::numbers::pi_v<long double>)) / area;
}

double ff_perpendicular_rectangles_offset(double x1, double x2, double y1, double y2, double eta1, double eta2,
                                          double z1, double z2) {
  require_finite({x1, y1, y2, eta1, eta2, z1});
  require_positive({x2 - x1, y2 - y1, eta2 - eta1, z2 - z1});
  require(x1 >= 0 && z1 >= 0, "the rectangles must lie on their sides of the common line (x1 >= 0, z1 >= 0)");
  const double area = (x2 - x1) * (y2 - y1);
  const double size = std::max(std::hypot(x2 - x1, y2 - y1), std::hypot(eta2 - eta1, z2 - z1));
  const double centres = std::hypot(0.5 * (x1 + x2), 0.5 * (y1 + y2 - eta1 - eta2), 0.5 * (z1 + z2));
  if (centres > 30 * size) {
    // F = 1/A_1 int int x z / (pi r^4): cos_1 = z / r, cos_2 = x / r.
    return integral_4d({x1, x2, y1, y2, eta1, eta2, z1, z2}, [](double x, double y, double eta, double z) {
             const double r2 = x * x + (y - eta) * (y - eta) + z * z;
             return x * z / (pi * r2 * r2);
           }) / area;
  }
  const std::array<long double, 2> x{x1, x2}, y{y1, y2}, eta{eta1, eta2}, z{z1, z2};
  const long double sum = corner_sum([&](int i, int j, int k, int l) {
    const long double s2 = x[i] * x[i] + z[l] * z[l], s = std::sqrt(s2), d = y[j] - eta[k];
    // Both terms vanish in the limit s, d -> 0 (a shared edge): skip them there.
    const long double along = s > 0 ? d * s * std::atan(d / s) : 0.0L;
    const long double logarithm = s2 + d * d > 0 ? (s2 - d * d) / 4 * std::log(s2 + d * d) : 0.0L;
    return along - logarithm;
  });
  return static_cast<double>(sum / (2 * std::numbers::pi_v<long double>)) / area;
}

}  // namespace gi
