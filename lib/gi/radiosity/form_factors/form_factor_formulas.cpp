#include "gi/radiosity/form_factors/form_factor_formulas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"
#include "gi/radiosity/mesh/convex_polygon.hpp"
#include "gi/radiosity/form_factors/quadrature.hpp"

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
    // gamma = atan2(sine, cosine), in (0, pi) as sine > 0, written as one arctangent:
    // of sine / cosine where cosine > 0, else pi/2 + atan(-cosine / sine); as exact as
    // atan2, to a rounding or two. Hierarchical radiosity takes millions of these, and
    // glibc's atan2 was a sixth of its time, its atan takes half of that.
    const double cosine = dot(a, b);
    const double gamma = cosine > 0 ? std::atan(sine / cosine) : pi / 2 - std::atan(cosine / sine);
    sum += gamma * dot(n, c) / sine;
  }
  return sum / (2 * pi);
  // END EXERCISE 6.2
}

double point_to_polygon_unchecked(const vec3& x, const vec3& n, const Polygon& polygon) {
  // x sees its back: nothing. And a point facing the way the polygon faces can never
  // see its front -- which also makes F_ii = 0 for a patch and its coplanar
  // neighbours, without trusting round-off (or a twisted wall's 3 mm) to decide.
  if (dot(polygon.normal, x - polygon.centre) <= 0 || dot(n, polygon.normal) > 1 - 1e-6) return 0;
  // The part in front of x's tangent plane (Sutherland-Hodgman against one plane). All
  // of it, for a source wholly in front (the usual case): its corners, as clip would
  // return them, without the copy.
  const double offset = dot(n, x);
  bool wholly_in_front = true;
  for (const vec3& corner : polygon.corners) wholly_in_front = wholly_in_front && dot(n, corner) - offset > 0;
  if (wholly_in_front) return contour_integral(x, n, polygon.corners.data(), 4);
  const ConvexPolygon front = clip(outline(polygon), n, offset, 0.0);
  return front.count < 3 ? 0 : contour_integral(x, n, front.corners.data(), front.count);
}

double form_factor_point_to_polygon(const vec3& x, const vec3& n, const Polygon& polygon) {
  if (!is_finite(x) || !is_finite(n) || std::abs(length(n) - 1) > 1e-6)
    throw std::invalid_argument("point-to-polygon form factor: the point must be finite and its normal unit length");
  check(polygon);
  return point_to_polygon_unchecked(x, n, polygon);
}

double form_factor_analytic(const Polygon& from, const Polygon& to, int order) {
  return form_factor_analytic_range(from, to, order).mean;
}

FormFactorRange form_factor_analytic_range(const Polygon& from, const Polygon& to, int order,
                                           const std::function<bool(double s, double t)>& counts,
                                           std::span<const vec2> also_at) {
  if (order < 1 || order > 16) throw std::invalid_argument("analytic form factor: the order must lie in [1, 16]");
  check(from);
  check(to);
  return analytic_range_unchecked(from, to, order, counts, also_at);
}

FormFactorRange analytic_range_unchecked(const Polygon& from, const Polygon& to, int order,
                                         const std::function<bool(double s, double t)>& counts,
                                         std::span<const vec2> also_at) {
  const GaussRule& rule = gauss_legendre(order);
  const std::array<vec3, 4>& c = from.corners;
  FormFactorRange range{0, 1e300, -1e300};
  double counted = 0, counted_area = 0;  // the mean's sums over the points `counts` accepts
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) {
      // The bilinear map of the unit square onto `from`, and its area element.
      const double s = rule.nodes[i], u = rule.nodes[j];
      const vec3 x = bilinear(c, s, u);
      const vec3 ds = (1 - u) * (c[1] - c[0]) + u * (c[2] - c[3]);
      const vec3 du = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
      const double F = point_to_polygon_unchecked(x, from.normal, to);
      const double w = rule.weights[i] * rule.weights[j] * length(cross(ds, du));
      range.mean += w * F;
      if (counts && counts(s, u)) counted += w * F, counted_area += w;
      range.least = std::min(range.least, F), range.greatest = std::max(range.greatest, F);
    }
  range.mean = counted_area > 0 ? counted / counted_area : range.mean / from.area;
  for (const vec2& st : also_at) {
    const double F = point_to_polygon_unchecked(bilinear(c, st.x, st.y), from.normal, to);
    range.least = std::min(range.least, F), range.greatest = std::max(range.greatest, F);
  }
  return range;
}

}  // namespace gi
