// Lesson 06, step 0: the geometry of a form factor, and Nusselt's analogue, drawn from
// the numbers they stand for (studies.hpp).
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/atomic_file.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/mesh/polygon.hpp"
#include "gi/report/svg_canvas.hpp"
#include "gi/report/table.hpp"
#include "studies.hpp"

namespace lesson06 {
namespace {

using Point = gi::SvgCanvas::Point;

// An oblique view of the scene: turned 30 degrees about z, seen from 30 degrees above
// the horizon, orthographic (a sphere's outline is then a circle of its radius).
struct View {
  Point origin;  // where (0, 0, 0) lands, in pixels
  double scale;  // pixels per unit
  Point operator()(const gi::vec3& p) const {
    const double turn = 0.52, tilt = 0.52;
    const double x = p.x * std::cos(turn) - p.y * std::sin(turn), y = p.x * std::sin(turn) + p.y * std::cos(turn);
    return {origin.x + scale * x, origin.y - scale * (p.z * std::cos(tilt) + y * std::sin(tilt))};
  }
};

std::string number(double v, int digits) { return gi::format_number(v, digits, gi::Format::Fixed); }
double degrees(double radians) { return radians * 180 / gi::pi; }

// A square of side `side` centred at `centre`, facing along `normal`, corners
// counter-clockwise seen from the normal's side.
gi::Polygon square(const gi::vec3& centre, const gi::vec3& normal, double side) {
  const gi::vec3 n = gi::normalize(normal);
  const gi::vec3 u = gi::normalize(gi::cross(std::abs(n.z) < 0.9 ? gi::vec3(0, 0, 1) : gi::vec3(1, 0, 0), n));
  const gi::vec3 v = gi::cross(n, u);
  const double h = side / 2;
  return gi::make_polygon({centre - h * u - h * v, centre + h * u - h * v, centre + h * u + h * v, centre - h * u + h * v});
}

std::vector<Point> outline(const gi::Polygon& polygon, const View& view) {
  std::vector<Point> points;
  for (const gi::vec3& c : polygon.corners) points.push_back(view(c));
  return points;
}

// The arc of radius `radius` about `centre` from direction a to direction b (unit
// vectors), drawn through the angle between them.
std::vector<Point> arc(const gi::vec3& centre, const gi::vec3& a, const gi::vec3& b, double radius, const View& view) {
  std::vector<Point> points;
  for (int k = 0; k <= 24; ++k) {
    const double t = k / 24.0;
    points.push_back(view(centre + radius * gi::normalize((1 - t) * a + t * b)));
  }
  return points;
}

// Left: two patches, their normals, the line between them and the two angles, with
// F from the small patch's centre to the other by the differential formula.
void two_patches(gi::SvgCanvas& canvas, gi::Lesson& lesson) {
  const View view{{150, 300}, 120};
  const gi::Polygon i = square({0, 0, 0}, {0, 0, 1}, 0.5), j = square({1.3, 0.5, 1.25}, {-0.2, -0.9, -0.6}, 0.6);
  const gi::vec3 d = j.centre - i.centre;
  const double r = gi::length(d), cos_i = gi::dot(i.normal, d) / r, cos_j = -gi::dot(j.normal, d) / r;
  const double F = cos_i * cos_j * j.area / (gi::pi * r * r);
  canvas.polygon(outline(i, view), "fill=\"#ddd\" stroke=\"black\"");
  canvas.polygon(outline(j, view), "fill=\"#cde\" stroke=\"black\"");
  canvas.line(view(i.centre), view(j.centre), "stroke=\"black\" stroke-dasharray=\"6 4\"");
  canvas.arrow(view(i.centre), view(i.centre + 0.8 * i.normal), "#D55E00");
  canvas.arrow(view(j.centre), view(j.centre + 0.8 * j.normal), "#D55E00");
  canvas.polyline(arc(i.centre, i.normal, d / r, 0.35, view), "fill=\"none\" stroke=\"#0072B2\" stroke-width=\"2\"");
  canvas.polyline(arc(j.centre, j.normal, -d / r, 0.35, view), "fill=\"none\" stroke=\"#0072B2\" stroke-width=\"2\"");
  const auto label = [&](const gi::vec3& at, const std::string& words) { canvas.text(view(at), words); };
  label(i.centre + gi::vec3(0.05, -0.45, 0), "dA_i");
  label(j.centre + gi::vec3(0.1, 0.1, 0.3), "A_j = " + number(j.area, 2));
  label(i.centre + gi::vec3(0.25, 0, 0.5), "θ_i = " + number(degrees(std::acos(cos_i)), 0) + "°");
  label(j.centre + gi::vec3(-0.75, 0, -0.25), "θ_j = " + number(degrees(std::acos(cos_j)), 0) + "°");
  label(0.5 * (i.centre + j.centre) + gi::vec3(0.3, 0, -0.15), "r = " + number(r, 2));
  label(i.centre + gi::vec3(-0.3, 0, 0.95), "n_i");
  label(j.centre + 0.85 * j.normal + gi::vec3(0.15, 0, 0), "n_j");
  canvas.text({20, 30}, "The differential form factor", "start", 15, "font-weight=\"bold\"");
  canvas.text({20, 345}, "F ≈ cos θ_i cos θ_j A_j / (π r²) = " + number(F, 4), "start", 14);
  lesson.say("the differential form factor of the figure: theta_i = " + number(degrees(std::acos(cos_i)), 1) +
             " degrees, theta_j = " + number(degrees(std::acos(cos_j)), 1) + " degrees, r = " + number(r, 3) +
             ", A_j = " + number(j.area, 2) + ": F = " + number(F, 4) + " (the exact point-to-patch value " +
             number(gi::form_factor_point_to_polygon(i.centre, i.normal, j), 4) + ")");
}

// Right: Nusselt's analogue. A patch above the unit hemisphere over a point is
// projected onto the hemisphere (towards the point), then straight down onto its
// base: the share of the base's disc it covers is the form factor.
void nusselt(gi::SvgCanvas& canvas, gi::Lesson& lesson) {
  const View view{{620, 240}, 125};
  const gi::Polygon patch = square({0.55, 0.45, 1.05}, {0, 0, -1}, 0.9);
  std::vector<gi::vec3> edge;  // the patch's outline, finely
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 64; ++k)
      edge.push_back(glm::mix(patch.corners[c], patch.corners[(c + 1) % 4], k / 64.0));
  std::vector<Point> base, sphere, disc;
  double area = 0;  // of the patch's image on the disc (the shoelace formula)
  for (int k = 0; k <= 96; ++k) {
    const double t = 2 * gi::pi * k / 96;
    base.push_back(view({std::cos(t), std::sin(t), 0}));
  }
  std::vector<Point> silhouette;  // orthographic: the sphere's outline is a circle of radius 1
  for (int k = 0; k <= 48; ++k) {
    const double t = gi::pi * k / 48;
    silhouette.push_back({view.origin.x + view.scale * std::cos(t), view.origin.y - view.scale * std::sin(t)});
  }
  for (std::size_t k = 0; k < edge.size(); ++k) {
    const gi::vec3 on_sphere = gi::normalize(edge[k]), next = gi::normalize(edge[(k + 1) % edge.size()]);
    sphere.push_back(view(on_sphere));
    disc.push_back(view({on_sphere.x, on_sphere.y, 0}));
    area += 0.5 * (on_sphere.x * next.y - next.x * on_sphere.y);
  }
  canvas.polygon(base, "fill=\"#f4f4f4\" stroke=\"black\"");
  canvas.polyline(silhouette, "fill=\"none\" stroke=\"black\"");
  canvas.polygon(disc, "fill=\"#0072B2\" fill-opacity=\"0.45\" stroke=\"#0072B2\"");
  canvas.polygon(outline(patch, view), "fill=\"#cde\" stroke=\"black\"");
  for (const gi::vec3& c : patch.corners) {
    const gi::vec3 s = gi::normalize(c);
    canvas.line(view({0, 0, 0}), view(c), "stroke=\"#999\"");
    canvas.line(view(s), view({s.x, s.y, 0}), "stroke=\"#0072B2\" stroke-dasharray=\"4 3\"");
  }
  sphere.push_back(sphere.front());
  canvas.polyline(sphere, "fill=\"none\" stroke=\"#0072B2\" stroke-width=\"2\"");
  canvas.arrow(view({0, 0, 0}), view({0, 0, 0.45}), "#D55E00");
  area = std::abs(area);  // the outline runs clockwise seen from above: the patch faces down
  const double F = area / gi::pi, exact = gi::form_factor_point_to_polygon({0, 0, 0}, {0, 0, 1}, patch);
  canvas.text({470, 30}, "Nusselt's analogue", "start", 15, "font-weight=\"bold\"");
  canvas.text(view(patch.corners[1] + gi::vec3(0.1, 0, 0.05)), "A_j");
  canvas.text({470, 325}, "F = (area of the image on the disc) / π = " + number(F, 4), "start", 14);
  canvas.text({470, 345}, "the contour integral: " + number(exact, 4), "start", 14);
  lesson.say("Nusselt's analogue of the figure: the patch's image covers " + number(area, 4) +
             " of the unit disc's area pi, F = " + number(F, 4) + "; the contour integral gives " + number(exact, 4));
}

}  // namespace

void geometry_figure(gi::Lesson& lesson) {
  gi::SvgCanvas canvas(900, 370);
  two_patches(canvas, lesson);
  nusselt(canvas, lesson);
  lesson.file("form_factor_geometry.svg", gi::OutputKind::Chart,
              "the form factor's geometry: two patches with their normals, the angles and the distance "
              "(left); Nusselt's analogue, a patch projected onto the unit hemisphere and down onto its disc (right)",
              [&](const std::filesystem::path& file) {
                gi::write_atomically(file, [&](std::ostream& out) { out << canvas.svg(); });
              });
  std::cout << '\n';
}

}  // namespace lesson06
