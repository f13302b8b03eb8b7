#pragma once
#include <sstream>
#include <string>
#include <vector>

namespace gi {

// A figure drawn by code as SVG: lines, arrows, polygons and text in the picture's own
// pixels (y downwards). For diagrams a lesson computes (lesson 06's form-factor
// geometry), where a chart's axes would be in the way. Text is escaped; numbers are
// written the same whatever the locale.
class SvgCanvas {
 public:
  struct Point {
    double x, y;
  };
  SvgCanvas(int width, int height);

  // `style` is SVG presentation attributes, e.g. "stroke=\"black\" stroke-width=\"2\"".
  void line(Point a, Point b, const std::string& style = "stroke=\"black\"");
  void arrow(Point from, Point to, const std::string& colour = "black");  // a line with a head at `to`
  void polyline(const std::vector<Point>& points, const std::string& style = "fill=\"none\" stroke=\"black\"");
  void polygon(const std::vector<Point>& points, const std::string& style);
  // `anchor`: "start", "middle" or "end".
  void text(Point at, const std::string& words, const std::string& anchor = "start", int size = 13,
            const std::string& style = "");

  int width() const { return width_; }
  int height() const { return height_; }
  std::string svg() const;  // the whole file

 private:
  int width_, height_;
  std::ostringstream body_;
};

std::string svg_escape(const std::string& text);  // <, >, & and " as entities
std::string svg_number(double v);                  // two decimals, "-1.25", whatever the locale

}  // namespace gi
