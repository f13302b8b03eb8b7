#include "gi/radiosity/form_factors/double_contour.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace gi {

namespace {

// In gi::wide (gi/core/wide_float.hpp), a margin: the pieces' integrals are of size one
// where a thin strip's form factor is 1e-6, and each would have to keep 1e-16 of itself
// to leave 1e-10 of that. What keeps those digits in double is taking a thin polygon's
// opposite sides together (line_integral_of_log_difference below).
using lvec3 = glm::vec<3, wide>;

// int_0^length ln(|x - (start + t e)| / scale) dt for a unit direction e: the
// antiderivative G(u) = u ln(sqrt(u^2 + d^2) / scale) - u + d atan(u / d) between the
// ends u1 = -foot and u2 = length - foot, u measured from the foot of the
// perpendicular from x. The two arctangents as one, atan2(d length, d^2 + u1 u2) (the
// angle between the ends seen from x), for speed. Dividing r by the polygons' size
// changes nothing (the contours are closed, so a constant under the integral adds up
// to zero) but keeps the terms small and their round-off with them.
wide line_integral_of_log(const lvec3& x, const lvec3& start, const lvec3& e, wide length, wide scale) {
  const lvec3 w = x - start;
  const wide foot = glm::dot(w, e);
  const lvec3 off = glm::cross(w, e);
  const wide d2 = glm::dot(off, off), d = std::sqrt(d2);  // not |w|^2 - foot^2: no cancellation
  const wide u1 = -foot, u2 = length - foot;
  const auto u_log_r = [&](wide u) {  // -> 0 as u and d -> 0
    return u == 0 ? wide(0) : 0.5 * u * std::log((u * u + d2) / (scale * scale));
  };
  return u_log_r(u2) - u_log_r(u1) - length + d * std::atan2(d * length, d2 + u1 * u2);
}

// The same integral along the segment moved by `shift` (at right angles to e) less the
// integral along the segment itself, without subtracting the two: for a thin polygon's
// two long sides the two are nearly equal, and their difference is what the form
// factor is made of. With d'^2 - d^2 = |c|^2 - 2 off . c (c = shift x e) and
// d' - d = (d'^2 - d^2) / (d' + d), the logarithms' difference is a log1p and the
// angles' difference one atan2, each exact to round-off of the difference itself.
wide line_integral_of_log_difference(const lvec3& x, const lvec3& start, const lvec3& e, wide length,
                                     const lvec3& shift) {
  const lvec3 w = x - start;
  const wide foot = glm::dot(w, e);
  const lvec3 off = glm::cross(w, e), c = glm::cross(shift, e), off_moved = off - c;
  const wide d2 = glm::dot(off, off), d2_moved = glm::dot(off_moved, off_moved);
  const wide change = glm::dot(c, c) - 2 * glm::dot(off, c);  // d'^2 - d^2
  const wide d = std::sqrt(d2), d_moved = std::sqrt(d2_moved);
  const wide u1 = -foot, u2 = length - foot, p = u1 * u2;
  const auto u_log_r = [&](wide u) {  // u/2 ln((u^2 + d'^2) / (u^2 + d^2)), -> 0 as u -> 0
    if (u == 0) return wide(0);
    const wide r2 = u * u + d2;
    return 0.5 * u * (std::abs(change) < 0.5 * r2 ? std::log1p(change / r2) : std::log((u * u + d2_moved) / r2));
  };
  // d' angle' - d angle. While d and d' are close, (d' - d) angle' + d (angle' - angle);
  // otherwise nothing cancels (and far from the line the change of d^2 is itself a
  // difference of large numbers): as it stands.
  const wide angle_moved = std::atan2(d_moved * length, d2_moved + p);
  wide angles = 0;
  if (d_moved <= 2 * d && d <= 2 * d_moved) {
    const wide dd = change / (d + d_moved);
    const wide angle_change =
        std::atan2(length * dd * (p - d * d_moved), d * d_moved * length * length + (d2_moved + p) * (d2 + p));
    angles = dd * angle_moved + d * angle_change;
  } else {
    angles = d_moved * angle_moved - d * std::atan2(d * length, d2 + p);
  }
  return u_log_r(u2) - u_log_r(u1) + angles;
}

// A polygon's area over its perimeter squared: small for a thin one (a w x l strip
// gives about w / 4 l), 1/16 for a square.
wide roundness(const ConvexPolygon& p) {
  lvec3 twice_area(0);
  wide perimeter = 0;
  for (int k = 0; k < p.count; ++k) {
    const lvec3 a(p.corners[k]), b(p.corners[(k + 1) % p.count]);
    twice_area += glm::cross(a - lvec3(p.corners[0]), b - lvec3(p.corners[0]));
    perimeter += glm::length(b - a);
  }
  return perimeter > 0 ? 0.5 * glm::length(twice_area) / (perimeter * perimeter) : wide(0);
}

}  // namespace

Estimate form_factor_double_contour(const ConvexPolygon& from, const ConvexPolygon& to, double area_from,
                                    double relative_tolerance, int max_evaluations) {
  // The sum is the same with the polygons' roles exchanged; the thinner one's edges go
  // inside, where its opposite sides are taken together (below).
  const bool exchange = roundness(from) < roundness(to);
  const ConvexPolygon& outer = exchange ? to : from;
  const ConvexPolygon& inner = exchange ? from : to;
  wide scale = 0;
  for (int i = 0; i < outer.count; ++i)
    for (int j = 0; j < inner.count; ++j) scale = std::max(scale, glm::length(lvec3(outer.corners[i] - inner.corners[j])));
  // The inner polygon's edges. The two long sides of a thin rectangle -- antiparallel,
  // of the same length, one across from the other at right angles, each to the
  // round-off of the corners, and at most a quarter of their length apart -- are one
  // `paired` edge (the other is skipped): their two terms, equal and opposite but for
  // the distance between them, are one difference (line_integral_of_log_difference).
  // Not wider ones: there the terms cancel little, and the two terms apart converge in
  // fewer evaluations (a square's double contour takes 30% longer paired).
  struct Edge {
    lvec3 start, vector, e, shift;
    wide length;
    bool paired = false, skip = false;
  };
  std::array<Edge, 8> edges{};
  wide magnitude = 0;
  for (int b = 0; b < inner.count; ++b) {
    Edge& edge = edges[b];
    edge.start = lvec3(inner.corners[b]), edge.vector = lvec3(inner.corners[(b + 1) % inner.count]) - edge.start;
    edge.length = glm::length(edge.vector);
    edge.e = edge.length > 0 ? edge.vector / edge.length : lvec3(0);
    magnitude = std::max(magnitude, glm::length(edge.start));
  }
  const wide round_off = 8 * std::numeric_limits<double>::epsilon() * magnitude;
  for (int b = 0; b < inner.count; ++b)
    for (int o = b + 1; o < inner.count && edges[b].length > 0 && !edges[b].paired && !edges[b].skip; ++o) {
      if (edges[o].paired || edges[o].skip) continue;
      const lvec3 shift = edges[o].start + edges[o].vector - edges[b].start;  // the other runs back from there
      if (glm::length(edges[b].vector + edges[o].vector) <= round_off &&
          std::abs(glm::dot(shift, edges[b].e)) <= round_off && 4 * glm::length(shift) <= edges[b].length)
        edges[b].paired = true, edges[b].shift = shift, edges[o].skip = true;
    }
  std::vector<Integrand> pieces;
  for (int a = 0; a < outer.count; ++a) {
    const lvec3 a0(outer.corners[a]), a1(outer.corners[(a + 1) % outer.count]);
    const wide length_a = glm::length(a1 - a0);
    for (int b = 0; b < inner.count; ++b) {
      const Edge& edge = edges[b];
      if (length_a == 0 || edge.length == 0 || edge.skip) continue;
      const lvec3 e_a = (a1 - a0) / length_a;
      const wide cosine = glm::dot(e_a, edge.e);
      if (std::abs(cosine) < 1e-15) continue;  // edges at right angles add nothing
      const lvec3 start = edge.start, e_b = edge.e, shift = edge.shift;
      const wide length_b = edge.length;
      if (edge.paired)
        pieces.push_back({[=](wide s) {
                            return -cosine * line_integral_of_log_difference(a0 + s * e_a, start, e_b, length_b, shift);
                          },
                          wide(0), length_a});
      else
        pieces.push_back(
            {[=](wide s) { return cosine * line_integral_of_log(a0 + s * e_a, start, e_b, length_b, scale); }, wide(0),
             length_a});
    }
  }
  const double to_form_factor = 1 / (2 * pi * area_from);
  const Estimate sum = integrate_adaptive(pieces, relative_tolerance, max_evaluations);
  return {sum.value * to_form_factor, sum.error * to_form_factor, sum.evaluations};
}

}  // namespace gi
