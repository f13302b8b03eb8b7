#include "gi/radiosity/mesh/convex_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi {

namespace {

// The distance between segments p0-p1 and q0-q1: minimise |p(s) - q(t)| over
// s, t in [0, 1], first without the bounds (the normal equations), then clamping
// one parameter and re-solving for the other.
double segment_distance(const vec3& p0, const vec3& p1, const vec3& q0, const vec3& q1) {
  const vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  if (a == 0 || e == 0) {  // a segment shrunk to a point
    const double s = a == 0 ? 0.0 : std::clamp(-c / a, 0.0, 1.0), t = e == 0 ? 0.0 : std::clamp(f / e, 0.0, 1.0);
    return length(p0 + s * d1 - (q0 + t * d2));
  }
  const double denominator = a * e - b * b;  // >= 0; 0 for parallel segments
  double s = denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0 || t > 1) {
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp((t * b - c) / a, 0.0, 1.0);
  }
  return length(p0 + s * d1 - (q0 + t * d2));
}

// The distance from x to p when x projects into p's interior; infinity otherwise
// (an edge is then nearer, and segment_distance finds it).
double face_distance(const vec3& x, const ConvexPolygon& p) {
  for (int k = 0; k < p.count; ++k) {
    const vec3& a = p.corners[k];
    const vec3& b = p.corners[(k + 1) % p.count];
    if (dot(cross(b - a, x - a), p.normal) < 0) return std::numeric_limits<double>::infinity();
  }
  return std::abs(dot(x - p.corners[0], p.normal));
}

}  // namespace

ConvexPolygon outline(const Polygon& polygon) {
  ConvexPolygon p;
  for (const vec3& c : polygon.corners) p.corners[p.count++] = c;
  p.normal = polygon.normal;
  return p;
}

bool is_flat(const Polygon& polygon) {
  const auto& c = polygon.corners;  // squared, to spare two square roots per polygon per hemicube
  const double size2 = std::max(dot(c[2] - c[0], c[2] - c[0]), dot(c[3] - c[1], c[3] - c[1]));
  for (const vec3& corner : c) {
    const double off = dot(corner - polygon.centre, polygon.normal);
    if (off * off > 1e-18 * size2) return false;
  }
  return true;
}

FlatPieces flat_pieces(const Polygon& polygon) {
  if (is_flat(polygon)) return {{outline(polygon)}, 1};
  const auto& c = polygon.corners;
  FlatPieces flat;
  flat.count = 2;
  for (int t = 0; t < 2; ++t) {  // (c0 c1 c2), then (c0 c2 c3)
    ConvexPolygon& triangle = flat.pieces[t];
    triangle.corners[0] = c[0], triangle.corners[1] = c[1 + t], triangle.corners[2] = c[2 + t];
    triangle.count = 3;
    triangle.normal = normalize(cross(c[1 + t] - c[0], c[2 + t] - c[0]));
  }
  return flat;
}

ConvexPolygon clip(const ConvexPolygon& p, const vec3& n, double offset, double tolerance) {
  // Signed distances, snapped to 0 within the tolerance (Sutherland-Hodgman, one plane).
  std::array<double, 8> d{};
  bool any_in_front = false;
  for (int k = 0; k < p.count; ++k) {
    d[k] = dot(n, p.corners[k]) - offset;
    if (std::abs(d[k]) <= tolerance) d[k] = 0;
    any_in_front = any_in_front || d[k] > 0;
  }
  ConvexPolygon out;
  out.normal = p.normal;
  if (!any_in_front) return out;
  for (int k = 0; k < p.count && out.count < 8; ++k) {
    const int next = (k + 1) % p.count;
    if (d[k] >= 0) out.corners[out.count++] = p.corners[k];
    if (((d[k] > 0 && d[next] < 0) || (d[k] < 0 && d[next] > 0)) && out.count < 8)
      out.corners[out.count++] = p.corners[k] + (d[k] / (d[k] - d[next])) * (p.corners[next] - p.corners[k]);
  }
  return out;
}

double area(const ConvexPolygon& p, const vec3& n) {
  vec3 sum(0.0);  // the shoelace formula in 3D: half the sum of the corners' cross products
  for (int k = 0; k < p.count; ++k) sum += cross(p.corners[k], p.corners[(k + 1) % p.count]);
  return 0.5 * std::abs(dot(sum, n));
}

double diameter(const ConvexPolygon& p) {
  double most = 0;
  for (int i = 0; i < p.count; ++i)
    for (int j = i + 1; j < p.count; ++j) most = std::max(most, length(p.corners[i] - p.corners[j]));
  return most;
}

double distance(const ConvexPolygon& a, const ConvexPolygon& b) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < a.count; ++i) {
    nearest = std::min(nearest, face_distance(a.corners[i], b));
    for (int j = 0; j < b.count; ++j)
      nearest = std::min(nearest, segment_distance(a.corners[i], a.corners[(i + 1) % a.count], b.corners[j],
                                                   b.corners[(j + 1) % b.count]));
  }
  for (int j = 0; j < b.count; ++j) nearest = std::min(nearest, face_distance(b.corners[j], a));
  return nearest;
}

double overlap_area(const ConvexPolygon& a, const ConvexPolygon& b) {
  ConvexPolygon shared = b;
  for (int k = 0; k < shared.count; ++k)  // projected onto a's plane
    shared.corners[k] -= dot(shared.corners[k] - a.corners[0], a.normal) * a.normal;
  for (int k = 0; k < a.count && shared.count > 0; ++k) {
    const vec3 edge = a.corners[(k + 1) % a.count] - a.corners[k];
    const vec3 inward = normalize(cross(a.normal, edge));  // a is counter-clockwise about its normal
    shared = clip(shared, inward, dot(inward, a.corners[k]), 0.0);
  }
  return area(shared, a.normal);
}

}  // namespace gi
