#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "gi/radiosity/mesh/convex_polygon.hpp"
#include "gi/radiosity/form_factors/double_contour.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"

namespace gi {

namespace {

// Gaps, as multiples of the polygons' widths, that choose the way of integrating.
constexpr double near_field = 0.25;  // below: the double contour integral
constexpr double far_field = 8;      // above: Gauss rules over both polygons
constexpr int highest_order = 32;

// Gauss points and weights over a convex polygon: the tensor rule on the bilinear
// map of a quadrilateral, Duffy's collapsed rule on each triangle of a fan otherwise
// (x = a + u (b - a) + u v (c - b), dA = 2 area(abc) u du dv). The weights add up to
// the area.
struct Node {
  vec3 x;
  double weight;
};
std::vector<Node> area_nodes(const ConvexPolygon& p, int order) {
  const GaussRule& rule = gauss_legendre(order);
  std::vector<Node> nodes;
  const auto& c = p.corners;
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) {
      const double u = rule.nodes[i], v = rule.nodes[j], w = rule.weights[i] * rule.weights[j];
      if (p.count == 4) {
        const vec3 du = (1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]), dv = (1 - u) * (c[3] - c[0]) + u * (c[2] - c[1]);
        nodes.push_back({bilinear({c[0], c[1], c[2], c[3]}, u, v), w * std::abs(dot(cross(du, dv), p.normal))});
        continue;
      }
      for (int k = 1; k + 1 < p.count; ++k) {
        const vec3 &a = c[0], &b = c[k], &d = c[k + 1];
        nodes.push_back({a + u * (b - a) + u * v * (d - b), w * std::abs(dot(cross(b - a, d - a), p.normal)) * u});
      }
    }
  return nodes;
}

// Far apart: the double area integral itself, cos_i cos_j / (pi r^2) at every pair
// of points -- positive and smooth, so nothing cancels and the rules converge fast.
double far_rule(const ConvexPolygon& from, const ConvexPolygon& to, int order, int& evaluations) {
  const std::vector<Node> xs = area_nodes(from, order), ys = area_nodes(to, order);
  evaluations += static_cast<int>(xs.size() * ys.size());
  double sum = 0;
  for (const Node& x : xs)
    for (const Node& y : ys) {
      const vec3 d = y.x - x.x;
      const double r2 = dot(d, d);
      sum += x.weight * y.weight * dot(from.normal, d) * -dot(to.normal, d) / (pi * r2 * r2);
    }
  return sum;
}

// Nearer: Lambert's contour integral to `to` (exact from a point) over the sender.
// Far away its edge terms cancel, which is why the far rule takes over there.
double contour_rule(const ConvexPolygon& from, const ConvexPolygon& to, int order, int& evaluations) {
  const std::vector<Node> xs = area_nodes(from, order);
  evaluations += static_cast<int>(xs.size());
  double sum = 0;
  for (const Node& x : xs) sum += x.weight * contour_integral(x.x, from.normal, to.corners.data(), to.count);
  return sum;
}

// Rules of rising order until two agree: the difference bounds the lower one's error,
// so it is a generous estimate of the higher one's. Nothing (NaN) if none agree.
template <class Rule>
Estimate converge(const Rule& rule, int first_order, int last_order, double area, double tolerance) {
  Estimate e{std::numeric_limits<double>::quiet_NaN(), 0, 0};
  double previous = std::numeric_limits<double>::quiet_NaN();
  for (int order = first_order; order <= last_order; order *= 2) {
    const double value = rule(order, e.evaluations) / area;
    const double error = std::abs(value - previous);
    const double round_off = 64 * std::numeric_limits<double>::epsilon() * std::abs(value);
    if (error <= std::max(tolerance * std::abs(value), round_off)) return {value, std::max(error, round_off), e.evaluations};
    previous = value;
  }
  return e;
}

// Cuts p to the part strictly in front of the plane n . x = offset. A corner whose
// distance from the plane is within the round-off of computing it (about 1e-16 of the
// coordinates' size) counts as in the plane: a receiver sharing an edge with the
// sender keeps that edge exactly, with no sliver of round-off beside it.
ConvexPolygon front_part(const ConvexPolygon& p, const vec3& n, double offset) {
  double magnitude = std::abs(offset);
  for (int k = 0; k < p.count; ++k) magnitude = std::max(magnitude, length(p.corners[k]));
  return clip(p, n, offset, 32 * std::numeric_limits<double>::epsilon() * magnitude);
}

// From a flat sender to a flat receiver (both counter-clockwise about their normals),
// each cut to the part in front of the other.
Estimate flat_to_flat(ConvexPolygon sender, ConvexPolygon receiver, double area, double tolerance, int first_order) {
  const vec3 n_i = sender.normal, n_j = receiver.normal;
  const double receiver_plane = dot(n_j, receiver.corners[0]);
  receiver = front_part(receiver, n_i, dot(n_i, sender.corners[0]));
  sender = front_part(sender, n_j, receiver_plane);
  if (receiver.count < 3 || sender.count < 3) return {0, 0, 0};

  const double gap = distance(sender, receiver), width = diameter(sender);
  if (gap >= far_field * std::max(width, diameter(receiver))) {
    const Estimate far = converge([&](int order, int& n) { return far_rule(sender, receiver, order, n); }, 4, 16,
                                  area, tolerance);
    if (!std::isnan(far.value)) return far;
  }
  if (gap >= near_field * width) {
    const Estimate mid = converge([&](int order, int& n) { return contour_rule(sender, receiver, order, n); },
                                  first_order, highest_order, area, tolerance);
    if (!std::isnan(mid.value)) return mid;
  }
  return form_factor_double_contour(sender, receiver, area, tolerance);
}

}  // namespace

Estimate form_factor_analytic_adaptive(const Polygon& from, const Polygon& to, double tolerance, int first_order) {
  check(from);
  check(to);
  if (!(tolerance >= 1e-14 && tolerance <= 0.1))
    throw std::invalid_argument("analytic form factor: the tolerance must lie in [1e-14, 0.1]");
  first_order = std::clamp(first_order, 1, highest_order);
  // The sender flattened onto the plane through its lifted centre; the receiver as the
  // rays meet it (its triangles, if it is twisted).
  const double top = dot(from.normal, lifted_centre(from));
  ConvexPolygon flat_sender = outline(from);
  for (int k = 0; k < 4; ++k) flat_sender.corners[k] += (top - dot(from.normal, flat_sender.corners[k])) * from.normal;
  const FlatPieces pieces = flat_pieces(to);
  Estimate sum;
  for (int p = 0; p < pieces.count; ++p) {
    const Estimate part = flat_to_flat(flat_sender, pieces.pieces[p], from.area, tolerance, first_order);
    sum.value += part.value, sum.error += part.error, sum.evaluations += part.evaluations;
  }
  return sum;
}

}  // namespace gi
