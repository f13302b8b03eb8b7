#include "gi/radiosity/form_factors/double_contour.hpp"

#include <cmath>
#include <vector>

namespace gi {

namespace {

// Long double throughout: the pieces' integrals are of size one where a thin strip's
// form factor is 1e-6, and each must keep 1e-16 of itself to leave 1e-10 of that.
using lvec3 = glm::vec<3, long double>;

// int_0^length ln(|x - (start + t e)| / scale) dt for a unit direction e: the
// antiderivative G(u) = u ln(sqrt(u^2 + d^2) / scale) - u + d atan(u / d) between the
// ends u1 = -foot and u2 = length - foot, u measured from the foot of the
// perpendicular from x. The two arctangents as one, atan2(d length, d^2 + u1 u2) (the
// angle between the ends seen from x), for speed. Dividing r by the polygons' size
// changes nothing (the contours are closed, so a constant under the integral adds up
// to zero) but keeps the terms small and their round-off with them.
long double line_integral_of_log(const lvec3& x, const lvec3& start, const lvec3& e, long double length,
                                 long double scale) {
  const lvec3 w = x - start;
  const long double foot = glm::dot(w, e);
  const lvec3 off = glm::cross(w, e);
  const long double d2 = glm::dot(off, off), d = std::sqrt(d2);  // not |w|^2 - foot^2: no cancellation
  const long double u1 = -foot, u2 = length - foot;
  const auto u_log_r = [&](long double u) {  // -> 0 as u and d -> 0
    return u == 0 ? 0.0L : 0.5L * u * std::log((u * u + d2) / (scale * scale));
  };
  return u_log_r(u2) - u_log_r(u1) - length + d * std::atan2(d * length, d2 + u1 * u2);
}

}  // namespace

Estimate form_factor_double_contour(const ConvexPolygon& from, const ConvexPolygon& to, double area_from,
                                    double relative_tolerance, int max_evaluations) {
  long double scale = 0;
  for (int i = 0; i < from.count; ++i)
    for (int j = 0; j < to.count; ++j) scale = std::max(scale, glm::length(lvec3(from.corners[i] - to.corners[j])));
  std::vector<Integrand> pieces;
  for (int a = 0; a < from.count; ++a) {
    const lvec3 a0(from.corners[a]), a1(from.corners[(a + 1) % from.count]);
    const long double length_a = glm::length(a1 - a0);
    for (int b = 0; b < to.count; ++b) {
      const lvec3 b0(to.corners[b]), b1(to.corners[(b + 1) % to.count]);
      const long double length_b = glm::length(b1 - b0);
      if (length_a == 0 || length_b == 0) continue;
      const lvec3 e_a = (a1 - a0) / length_a, e_b = (b1 - b0) / length_b;
      const long double cosine = glm::dot(e_a, e_b);
      if (std::abs(cosine) < 1e-15L) continue;  // edges at right angles add nothing
      pieces.push_back({[=](long double s) { return cosine * line_integral_of_log(a0 + s * e_a, b0, e_b, length_b, scale); },
                        0.0L, length_a});
    }
  }
  const double to_form_factor = 1 / (2 * pi * area_from);
  const Estimate sum = integrate_adaptive(pieces, relative_tolerance, max_evaluations);
  return {sum.value * to_form_factor, sum.error * to_form_factor, sum.evaluations};
}

}  // namespace gi
