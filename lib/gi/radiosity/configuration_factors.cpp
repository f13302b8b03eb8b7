#include "gi/radiosity/configuration_factors.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gi {

namespace {

constexpr double pi = std::numbers::pi;

void require_positive(double a, double b, double c) {
  if (!(a > 0 && b > 0 && c > 0 && std::isfinite(a) && std::isfinite(b) && std::isfinite(c)))
    throw std::invalid_argument("configuration factor: every length must be positive and finite");
}

}  // namespace

double ff_parallel_rectangles(double a, double b, double c) {
  require_positive(a, b, c);
  const double x = a / c, y = b / c;
  const double x2 = 1 + x * x, y2 = 1 + y * y;
  return 2 / (pi * x * y) *
         (0.5 * std::log(x2 * y2 / (x2 + y * y)) + x * std::sqrt(y2) * std::atan(x / std::sqrt(y2)) +
          y * std::sqrt(x2) * std::atan(y / std::sqrt(x2)) - x * std::atan(x) - y * std::atan(y));
}

double ff_perpendicular_rectangles(double l, double w, double h) {
  require_positive(l, w, h);
  const double W = w / l, H = h / l;
  const double w2 = W * W, h2 = H * H, s = w2 + h2;
  const double log_term = std::log((1 + w2) * (1 + h2) / (1 + s)) +
                          w2 * std::log(w2 * (1 + s) / ((1 + w2) * s)) +
                          h2 * std::log(h2 * (1 + s) / ((1 + h2) * s));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - std::sqrt(s) * std::atan(1 / std::sqrt(s)) +
          0.25 * log_term) /
         (pi * W);
}

double ff_point_to_parallel_rectangle_corner(double a, double b, double c) {
  require_positive(a, b, c);
  const double A = a / c, B = b / c;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * pi);
}

}  // namespace gi
