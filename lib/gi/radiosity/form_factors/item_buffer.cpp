#include "gi/radiosity/form_factors/item_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "gi/core/onb.hpp"
#include "gi/radiosity/mesh/convex_polygon.hpp"

namespace gi {

namespace {

// A face seen as a camera: it looks along `forward`; screen coordinates are
// (q.across, q.up) / q.forward, across in [-1, 1] and up in [-1, 1] (top) or [0, 1].
struct FaceView {
  int forward_axis;
  double forward_sign;
  int across_axis;
  int up_axis;
};
constexpr FaceView views[hemicube_faces] = {
    {2, 1, 0, 1},   // Top: looks along +z; columns x, rows y
    {0, 1, 1, 2},   // PlusX: columns y, rows z
    {0, -1, 1, 2},  // MinusX
    {1, 1, 0, 2},   // PlusY: columns x, rows z
    {1, -1, 0, 2},  // MinusY
};

constexpr int max_vertices = 8;
struct ClippedPolygon {
  std::array<vec3, max_vertices> v;
  int n = 0;
};

// Sutherland-Hodgman against the plane q[axis] * sign >= near: keeps what lies in
// front of the face, so that the division by the forward distance is safe. The cut is
// always computed from the edge's end in front, so that two polygons sharing the edge
// (walking it in opposite directions) get the very same point.
ClippedPolygon clip_near(const ClippedPolygon& q, int axis, double sign, double near) {
  ClippedPolygon out;
  for (int i = 0; i < q.n; ++i) {
    const vec3& a = q.v[i];
    const vec3& b = q.v[(i + 1) % q.n];
    const double da = sign * a[axis] - near, db = sign * b[axis] - near;
    if (da >= 0) out.v[out.n++] = a;
    if ((da >= 0) != (db >= 0))
      out.v[out.n++] = da >= 0 ? a + (da / (da - db)) * (b - a) : b + (db / (db - da)) * (a - b);
  }
  return out;
}

// The edge function of a -> b at (x, y): twice the signed area of the triangle a, b,
// (x, y). Set up with the endpoints in one fixed order (and the sign flipped when it
// is not a -> b), so that two polygons sharing the edge, which they walk in opposite
// directions, get exactly opposite values: a cell centre on the edge cannot round to
// "outside" for both and leave a crack.
struct EdgeFunction {
  vec2 from, along;
  double sign;
  double operator()(double x, double y) const { return sign * (along.x * (y - from.y) - along.y * (x - from.x)); }
};
EdgeFunction edge_function(const vec2& a, const vec2& b) {
  const bool ordered = a.x < b.x || (a.x == b.x && a.y < b.y);
  const vec2 &p = ordered ? a : b, &q = ordered ? b : a;
  return {p, q - p, ordered ? 1.0 : -1.0};
}

// The area of the part of a projected polygon inside the face, [-1, 1] x [bottom,
// top]: Sutherland-Hodgman against the sides its bounding box crosses, then the
// shoelace formula.
struct Bounds {
  double lo_x, hi_x, lo_y, hi_y;
};
double area_on_face(const std::array<vec2, max_vertices>& s, int n, double whole_area, const Bounds& image,
                    double bottom, double top) {
  if (image.hi_x <= -1 || image.lo_x >= 1 || image.hi_y <= bottom || image.lo_y >= top) return 0;  // on another face
  const bool crossed[4] = {image.lo_x < -1, image.hi_x > 1, image.lo_y < bottom, image.hi_y > top};
  if (!crossed[0] && !crossed[1] && !crossed[2] && !crossed[3]) return whole_area;
  std::array<std::array<vec2, max_vertices + 4>, 2> buffers;  // in and out, swapped per cut
  std::copy(s.begin(), s.begin() + n, buffers[0].begin());
  int current = 0;
  const double limit[4] = {-1, 1, bottom, top};
  for (int side = 0; side < 4 && n > 0; ++side) {
    if (!crossed[side]) continue;
    const auto& in = buffers[current];
    auto& out = buffers[1 - current];
    const int axis = side < 2 ? 0 : 1;
    const double sign = side % 2 ? -1.0 : 1.0;  // keep sign * (coordinate - limit) >= 0
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const vec2 &a = in[k], &b = in[(k + 1) % n];
      const double da = sign * (a[axis] - limit[side]), db = sign * (b[axis] - limit[side]);
      if (da >= 0) out[m++] = a;
      if ((da >= 0) != (db >= 0)) out[m++] = a + (da / (da - db)) * (b - a);
    }
    n = m, current = 1 - current;
  }
  const auto& last = buffers[current];
  double area2 = 0;
  for (int k = 0; k < n; ++k) area2 += last[k].x * last[(k + 1) % n].y - last[(k + 1) % n].x * last[k].y;
  return 0.5 * std::abs(area2);
}

// Rasterises one face's view of a clipped polygon; returns the cells its image covers.
double rasterise(const ClippedPolygon& p, const vec3& plane_normal, double plane_offset, int item, const FaceView& view,
                 int resolution, int rows, double row_origin, std::vector<int>& items, std::vector<double>& depths) {
  // Project onto the face: screen position (s, t) = (across, up) / forward.
  std::array<vec2, max_vertices> s;
  double area2 = 0;
  for (int k = 0; k < p.n; ++k) {
    const double f = view.forward_sign * p.v[k][view.forward_axis];
    s[k] = vec2(p.v[k][view.across_axis] / f, p.v[k][view.up_axis] / f);
  }
  for (int k = 0; k < p.n; ++k) area2 += s[k].x * s[(k + 1) % p.n].y - s[(k + 1) % p.n].x * s[k].y;
  if (std::abs(area2) < 1e-300) return 0;
  const double orientation = area2 > 0 ? 1.0 : -1.0;
  // The cells whose centres may lie inside: the projected bounding box.
  const double cell = 2.0 / resolution, top = row_origin + rows * cell;
  Bounds image{s[0].x, s[0].x, s[0].y, s[0].y};
  for (int k = 1; k < p.n; ++k) {
    image.lo_x = std::min(image.lo_x, s[k].x), image.hi_x = std::max(image.hi_x, s[k].x);
    image.lo_y = std::min(image.lo_y, s[k].y), image.hi_y = std::max(image.hi_y, s[k].y);
  }
  const auto [lo_x, hi_x, lo_y, hi_y] = image;
  // The image's area in cells, for a receiver.
  const double covered =
      item < 0 ? 0.0 : area_on_face(s, p.n, 0.5 * std::abs(area2), image, row_origin, top) / (cell * cell);
  std::array<EdgeFunction, max_vertices> edges;
  for (int k = 0; k < p.n; ++k) edges[k] = edge_function(s[k], s[(k + 1) % p.n]);
  // Clamped before the conversion: a polygon reaching close to the face's plane
  // projects to enormous coordinates that no int can hold. Widened by a hair: a cell
  // centre on the box's border (on an edge shared with a neighbour) must reach the
  // edge test, which alone decides, consistently, which of the two takes it.
  const auto first = [&](double lo, double origin, int cells) {
    return static_cast<int>(std::clamp(std::ceil((lo - origin) / cell - 0.5 - 1e-9), 0.0, double(cells)));
  };
  const auto last = [&](double hi, double origin, int cells) {
    return static_cast<int>(std::clamp(std::floor((hi - origin) / cell - 0.5 + 1e-9), -1.0, double(cells - 1)));
  };
  const int c0 = first(lo_x, -1, resolution), c1 = last(hi_x, -1, resolution);
  const int r0 = first(lo_y, row_origin, rows), r1 = last(hi_y, row_origin, rows);
  for (int row = r0; row <= r1; ++row) {
    const double y = row_origin + (row + 0.5) * cell;
    for (int column = c0; column <= c1; ++column) {
      const double x = -1 + (column + 0.5) * cell;
      bool inside = true;
      for (int k = 0; k < p.n && inside; ++k) inside = orientation * edges[k](x, y) >= 0;
      if (!inside) continue;
      // Exact depth: where the cell's ray d = forward + x across + y up meets the
      // polygon's plane n.q = offset, measured along the face's axis.
      vec3 d;
      d[view.forward_axis] = view.forward_sign;
      d[view.across_axis] = x;
      d[view.up_axis] = y;
      const double depth = plane_offset / dot(plane_normal, d);
      double& nearest = depths[row * resolution + column];
      int& shown = items[row * resolution + column];
      // Nearer wins; at a tie (to round-off: a cell centre on the edge where a front
      // face meets a back face, as on a block's top rim) the front face does, since a
      // back face hides only what lies behind it.
      if (!(depth > 0)) continue;
      if (depth < nearest * (1 - 1e-12) || (item >= 0 && shown < 0 && depth <= nearest * (1 + 1e-12))) {
        nearest = std::min(nearest, depth);
        shown = item;
      }
    }
  }
  return covered;
}

}  // namespace

void render_item_buffer(const std::vector<Polygon>& polygons, const vec3& centre, const vec3& normal, int resolution,
                        ItemBuffer& buffer) {
  for (std::size_t i = 0; i < polygons.size(); ++i) try {
      check(polygons[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("item buffer: polygon " + std::to_string(i) + ": " + e.what());
    }
  render_checked_item_buffer(polygons, centre, normal, resolution, buffer);
}

void render_checked_item_buffer(const std::vector<Polygon>& polygons, const vec3& centre, const vec3& normal,
                                int resolution, ItemBuffer& buffer) {
  if (resolution < 2 || resolution > 2000 || resolution % 2)
    throw std::invalid_argument("item buffer: the resolution must be even and lie in [2, 2000]");
  if (!is_finite(centre) || !is_finite(normal) || std::abs(length(normal) - 1) > 1e-6)
    throw std::invalid_argument("item buffer: the hemicube's centre must be finite and its normal unit length");
  buffer.resolution = resolution;
  for (int f = 0; f < hemicube_faces; ++f) {
    const std::size_t cells = static_cast<std::size_t>(buffer.rows(HemicubeFace(f))) * resolution;
    buffer.items[f].assign(cells, -1);
    buffer.depths[f].assign(cells, std::numeric_limits<double>::infinity());
  }
  buffer.footprint.assign(polygons.size(), 0.0);
  const Onb frame(normal);  // hemicube coordinates: x = frame.u, y = frame.v, z = normal
  const auto local = [&](const vec3& r) { return vec3(dot(r, frame.u), dot(r, frame.v), dot(r, normal)); };
  // One flat piece of polygon i: its corners moved into hemicube coordinates, then
  // onto every face it reaches.
  const auto draw = [&](int i, const vec3* corners, int count, const vec3& piece_normal) {
    ClippedPolygon q;
    double highest = 0, size = 0;
    for (int k = 0; k < count; ++k) {
      q.v[q.n++] = local(corners[k] - centre);
      highest = std::max(highest, q.v[k].z);
      size = std::max(size, length(corners[k] - centre));
    }
    const double near = 1e-9 * size;
    if (highest <= near) return;  // behind the base plane or in it
    const vec3 n = local(piece_normal);
    const double offset = dot(n, q.v[0]);  // the plane n.q = offset; the centre q = 0 is in front if offset < 0
    const int item = offset < 0 ? i : -1;
    for (int f = 0; f < hemicube_faces; ++f) {
      const FaceView& view = views[f];
      // Quick reject: nothing of the polygon in front of this face.
      bool any = false;
      for (int k = 0; k < q.n && !any; ++k) any = view.forward_sign * q.v[k][view.forward_axis] > near;
      if (!any) continue;
      const ClippedPolygon clipped = clip_near(q, view.forward_axis, view.forward_sign, near);
      if (clipped.n < 3) continue;
      const int rows = buffer.rows(HemicubeFace(f));
      const double cells = rasterise(clipped, n, offset, item, view, resolution, rows, f == 0 ? -1.0 : 0.0,
                                     buffer.items[f], buffer.depths[f]);
      if (item >= 0) buffer.footprint[i] += cells;
    }
  };
  for (int i = 0; i < static_cast<int>(polygons.size()); ++i) {
    const Polygon& p = polygons[i];
    if (is_flat(p)) {
      draw(i, p.corners.data(), 4, p.normal);
      continue;
    }
    // A twisted polygon is drawn as its two triangles: each has a plane to take depths
    // from, and they are what the rays of the other methods hit.
    const auto& c = p.corners;
    const vec3 first[3] = {c[0], c[1], c[2]}, second[3] = {c[0], c[2], c[3]};
    draw(i, first, 3, normalize(cross(c[1] - c[0], c[2] - c[0])));
    draw(i, second, 3, normalize(cross(c[2] - c[0], c[3] - c[0])));
  }
}

}  // namespace gi
