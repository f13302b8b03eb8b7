#pragma once
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "gi/radiosity/mesh/polygon.hpp"

namespace gi {

// The lecture's differential form factor, applied from centre to centre:
//   F_ij ~ cos(theta_i) cos(theta_j) / (pi r^2) * A_j * H_ij
// theta_i is the angle at x_i between n_i and the line to x_j, theta_j the angle at
// x_j between n_j and the line back; H_ij in [0, 1] is the visibility. Zero when
// either surface faces away from the other. Good when r is large against the patch
// sizes; wrong (even above 1) as the patches approach.
double form_factor_differential(const vec3& x_i, const vec3& n_i, const vec3& x_j, const vec3& n_j, double area_j,
                                double visibility);

// The form factor from a differential area at x (unit normal n) to a polygon, by
// Lambert's contour integral (exact, no occlusion):
//   F = 1/(2 pi) sum over edges k of gamma_k  n . (R_k+1 x R_k) / |R_k+1 x R_k|
// R_k = v_k - x, gamma_k the angle between R_k and R_k+1. The vertices go
// counter-clockwise seen from the polygon's front, which faces x, and lie on x's
// side of its tangent plane (form_factor_point_to_polygon makes sure of both).
double contour_integral(const vec3& x, const vec3& n, const vec3* vertices, int count);

// The same for any polygon: zero when x sees its back, the part below x's tangent
// plane clipped away. Throws std::invalid_argument for a non-finite point or normal
// and an invalid polygon (check).
double form_factor_point_to_polygon(const vec3& x, const vec3& n, const Polygon& polygon);
// The same without the checks, for callers whose point and polygon are known good (a
// hierarchy's nodes, made by make_polygon, which checks): the final gather takes a
// hundred of these a point, and checking the polygon each time was a sixth of its time.
double point_to_polygon_unchecked(const vec3& x, const vec3& n, const Polygon& polygon);

// Patch to patch: the point-to-polygon factor averaged over `from` with a fixed
// order x order Gauss-Legendre rule (order 1..16): F_ij = 1/A_i integral over A_i.
// Fast and exact to 1e-10 for patches a size apart, but with no error estimate and
// wrong by up to 1e-3 in the near field and at shared edges, where the integrand is
// not smooth; the analytic method itself is form_factor_analytic_adaptive.
double form_factor_analytic(const Polygon& from, const Polygon& to, int order);

// The same rule's mean, with the least and the greatest point-to-polygon F over its
// points: how much F changes across `from` (hierarchical radiosity's oracle). Given
// `counts`, the mean is over the points it accepts ((s, t) in from's parameter square:
// the part of `from` that matters, such as a quadtree node's open part), and over all
// of them if it accepts none; the least and greatest are always over all of them, and
// over the points `also_at` of from's parameter square too (where F may peak between
// the rule's points), which do not count in the mean.
struct FormFactorRange {
  double mean = 0, least = 0, greatest = 0;
};
FormFactorRange form_factor_analytic_range(const Polygon& from, const Polygon& to, int order,
                                           const std::function<bool(double s, double t)>& counts = {},
                                           std::span<const vec2> also_at = {});
// The same without checking the polygons and the order, for callers that made them
// (a hierarchy's nodes come from make_polygon, which checks): the hierarchy judges a
// million links, and the two polygons' checks were a twentieth of its time.
FormFactorRange analytic_range_unchecked(const Polygon& from, const Polygon& to, int order,
                                         const std::function<bool(double s, double t)>& counts,
                                         std::span<const vec2> also_at);

}  // namespace gi
