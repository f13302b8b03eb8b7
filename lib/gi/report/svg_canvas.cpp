#include "gi/report/svg_canvas.hpp"

#include <cmath>
#include <cstdlib>

namespace gi {

std::string svg_escape(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

// Two decimals, by integer arithmetic: printf would write the locale's decimal comma.
std::string svg_number(double v) {
  const long long hundredths = std::llround(v * 100), whole = std::llabs(hundredths) / 100;
  const long long cents = std::llabs(hundredths) % 100;
  return (hundredths < 0 ? "-" : "") + std::to_string(whole) + (cents < 10 ? ".0" : ".") + std::to_string(cents);
}

SvgCanvas::SvgCanvas(int width, int height) : width_(width), height_(height) {}

void SvgCanvas::line(Point a, Point b, const std::string& style) {
  body_ << "<line x1=\"" << svg_number(a.x) << "\" y1=\"" << svg_number(a.y) << "\" x2=\"" << svg_number(b.x)
        << "\" y2=\"" << svg_number(b.y) << "\" " << style << "/>\n";
}

void SvgCanvas::arrow(Point from, Point to, const std::string& colour) {
  line(from, to, "stroke=\"" + colour + "\" stroke-width=\"2\"");
  // A head 10 px long, 30 degrees either side of the shaft.
  const double dx = to.x - from.x, dy = to.y - from.y, length = std::hypot(dx, dy);
  if (length == 0) return;
  const double half_angle = 0.5235987755982988;  // 30 degrees, pi / 6
  const double ux = dx / length, uy = dy / length, c = std::cos(half_angle), s = std::sin(half_angle);
  const Point left{to.x - 10 * (c * ux - s * uy), to.y - 10 * (s * ux + c * uy)};
  const Point right{to.x - 10 * (c * ux + s * uy), to.y - 10 * (-s * ux + c * uy)};
  polygon({to, left, right}, "fill=\"" + colour + "\"");
}

void SvgCanvas::polyline(const std::vector<Point>& points, const std::string& style) {
  body_ << "<polyline points=\"";
  for (const Point& p : points) body_ << svg_number(p.x) << ',' << svg_number(p.y) << ' ';
  body_ << "\" " << style << "/>\n";
}

void SvgCanvas::polygon(const std::vector<Point>& points, const std::string& style) {
  body_ << "<polygon points=\"";
  for (const Point& p : points) body_ << svg_number(p.x) << ',' << svg_number(p.y) << ' ';
  body_ << "\" " << style << "/>\n";
}

void SvgCanvas::text(Point at, const std::string& words, const std::string& anchor, int size,
                     const std::string& style) {
  body_ << "<text x=\"" << svg_number(at.x) << "\" y=\"" << svg_number(at.y) << "\" text-anchor=\"" << anchor
        << "\" font-size=\"" << size << "\"" << (style.empty() ? "" : " " + style) << '>' << svg_escape(words)
        << "</text>\n";
}

std::string SvgCanvas::svg() const {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width_) + "\" height=\"" +
         std::to_string(height_) + "\" viewBox=\"0 0 " + std::to_string(width_) + ' ' + std::to_string(height_) +
         "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body_.str() +
         "</svg>\n";
}

}  // namespace gi
