#include "gi/radiosity/form_factor_formulas.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "gi/core/not_implemented.hpp"

namespace gi {

double form_factor_differential(const vec3& x_i, const vec3& n_i, const vec3& x_j, const vec3& n_j, double area_j,
                                double visibility) {
  // BEGIN EXERCISE 6.1 the differential form factor with visibility
  const vec3 d = x_j - x_i;
  const double r2 = dot(d, d);
  const double r = std::sqrt(r2);
  const double cos_i = dot(n_i, d) / r, cos_j = -dot(n_j, d) / r;
  if (cos_i <= 0 || cos_j <= 0) return 0;  // one of them faces away
  return cos_i * cos_j / (pi * r2) * area_j * visibility;
  // END EXERCISE 6.1
}

double contour_integral(const vec3& x, const vec3& n, const vec3* vertices, int count) {
  // BEGIN EXERCISE 6.2 the contour integral
  double sum = 0;
  for (int k = 0; k < count; ++k) {
    const vec3 a = vertices[k] - x, b = vertices[(k + 1) % count] - x;
    const vec3 c = cross(b, a);
    const double sine = length(c);
    if (sine == 0) continue;  // an edge pointing at x subtends no angle
    const double gamma = std::atan2(sine, dot(a, b));
    sum += gamma * dot(n, c) / sine;
  }
  return sum / (2 * pi);
  // END EXERCISE 6.2
}

double form_factor_point_to_polygon(const vec3& x, const vec3& n, const Polygon& polygon) {
  // x sees its back: nothing. And a point facing the way the polygon faces can never
  // see its front -- which also makes F_ii = 0 for a patch and its coplanar
  // neighbours, without trusting round-off (or a twisted wall's 3 mm) to decide.
  if (dot(polygon.normal, x - polygon.centre) <= 0 || dot(n, polygon.normal) > 1 - 1e-6) return 0;
  // Clip to the half-space in front of x (Sutherland-Hodgman against one plane).
  vec3 clipped[8];
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    const vec3& a = polygon.corners[k];
    const vec3& b = polygon.corners[(k + 1) % 4];
    const double da = dot(n, a - x), db = dot(n, b - x);
    if (da >= 0) clipped[count++] = a;
    if ((da >= 0) != (db >= 0)) clipped[count++] = a + (da / (da - db)) * (b - a);
  }
  return count < 3 ? 0 : contour_integral(x, n, clipped, count);
}

namespace {

// Nodes and weights of the n-point Gauss-Legendre rule on [0, 1], by Newton's method
// on the Legendre polynomial P_n from the usual cosine guesses.
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.resize(n), weights.resize(n);
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
    nodes[i] = 0.5 * (1 - z);
    weights[i] = 1.0 / ((1 - z * z) * derivative * derivative);  // 2 / (...) on [-1, 1], halved on [0, 1]
  }
}

}  // namespace

double form_factor_analytic(const Polygon& from, const Polygon& to, int order) {
  if (order < 1 || order > 16) throw std::invalid_argument("analytic form factor: the order must lie in [1, 16]");
  std::vector<double> t, w;
  gauss_legendre(order, t, w);
  const std::array<vec3, 4>& c = from.corners;
  double sum = 0;
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) {
      // The bilinear map of the unit square onto `from`, and its area element.
      const double s = t[i], u = t[j];
      const vec3 x = bilinear(c, s, u);
      const vec3 ds = (1 - u) * (c[1] - c[0]) + u * (c[2] - c[3]);
      const vec3 du = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
      sum += w[i] * w[j] * length(cross(ds, du)) * form_factor_point_to_polygon(x, from.normal, to);
    }
  return sum / from.area;
}

}  // namespace gi
