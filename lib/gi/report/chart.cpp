#include "gi/report/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "gi/core/atomic_file.hpp"
#include "gi/report/svg_canvas.hpp"

namespace gi {

namespace {

// Okabe-Ito: distinguishable with the common colour-vision deficiencies.
const char* const palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};

std::string escape(const std::string& s) { return svg_escape(s); }
std::string num(double v) { return svg_number(v); }  // fixed formatting, independent of the locale

// Ticks of everyday size read as %g (0.02, 300); on a log axis the very small and
// very large as 2e-5, 1e6.
std::string tick_label(double v, bool log) {
  char buffer[32];
  // The decade of v; none for 0, whose log is -inf (no int holds it).
  const int e = v != 0 ? static_cast<int>(std::floor(std::log10(std::abs(v)) + 1e-9)) : 0;
  if (log && (e < -3 || e > 4)) std::snprintf(buffer, sizeof buffer, "%.3ge%d", v / power_of_ten(e), e);
  else std::snprintf(buffer, sizeof buffer, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buffer;
}

struct Axis {
  double lo, hi;
  bool log;
  double map(double v, double from, double to) const {  // data value to pixel
    const double a = log ? std::log10(lo) : lo, b = log ? std::log10(hi) : hi;
    const double x = log ? std::log10(v) : v;
    return from + (x - a) / (b - a) * (to - from);
  }
};

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

// The data range of one axis, widened to whole ticks.
Axis make_axis(const Chart& chart, bool x_axis) {
  const bool log = x_axis ? chart.log_x : chart.log_y;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : chart.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!usable(x, chart.log_x) || !usable(y, chart.log_y)) continue;
      const double v = x_axis ? x : y;
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
  if (!(lo <= hi)) lo = log ? 1 : 0, hi = log ? 10 : 1;
  if (lo == hi) lo = log ? lo / 10 : lo - 1, hi = log ? hi * 10 : hi + 1;
  const std::vector<double> ticks = axis_ticks(lo, hi, log);
  return {std::min(lo, ticks.front()), std::max(hi, ticks.back()), log};
}

}  // namespace

namespace {

// The values m 10^e (m from `mantissas`) from the largest at or below lo to the
// smallest at or above hi.
std::vector<double> log_ticks(double lo, double hi, const std::vector<int>& mantissas) {
  std::vector<double> all;
  for (int e = static_cast<int>(std::floor(std::log10(lo))) - 1; e <= static_cast<int>(std::ceil(std::log10(hi))); ++e)
    for (int m : mantissas) all.push_back(m * power_of_ten(e));
  std::vector<double> ticks;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const bool below = i + 1 < all.size() && all[i + 1] <= lo * (1 + 1e-12);
    const bool above = i > 0 && all[i - 1] >= hi * (1 - 1e-12);
    if (!below && !above) ticks.push_back(all[i]);
  }
  return ticks;
}

}  // namespace

double power_of_ten(int e) {
  if (e < -22 || e > 22) return std::pow(10.0, e);  // beyond the exact powers: as near as pow gives
  double p = 1;
  for (int i = 0; i < std::abs(e); ++i) p *= 10;  // exact: 10^22 = 2^22 5^22 and 5^22 < 2^53
  return e < 0 ? 1 / p : p;
}

std::vector<double> axis_ticks(double lo, double hi, bool log) {
  if (log) {
    // Decades when they give four ticks or more; over a narrower range 1-2-5, then
    // every digit, then plain steps, so that a log axis always carries a few labels.
    for (const std::vector<int>& mantissas : {std::vector<int>{1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
      std::vector<double> ticks = log_ticks(lo, hi, mantissas);
      if (ticks.size() >= 4) return ticks;
    }
    std::vector<double> ticks;
    for (double t : axis_ticks(lo, hi, false))
      if (t > 0) ticks.push_back(t);
    return ticks;
  }
  std::vector<double> ticks;
  // The smallest step of the form {1, 2, 5} x 10^k that gives at most 8 intervals.
  const double raw = (hi - lo) / 8;
  const double decade = power_of_ten(static_cast<int>(std::floor(std::log10(raw))));
  double step = decade * 10;
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) {
      step = m * decade;
      break;
    }
  for (double t = std::floor(lo / step) * step; t <= std::ceil(hi / step) * step + 0.5 * step; t += step)
    ticks.push_back(t);
  return ticks;
}

std::string to_svg(const Chart& chart, int width, int height) {
  const double left = 80, right = width - 200.0, top = 40, bottom = height - 60.0;
  const Axis ax = make_axis(chart, true), ay = make_axis(chart, false);
  // The legend sits right of the plot; a long series name or title widens the picture
  // rather than being cut off (about 7 px a character at font size 12, 8 at 15).
  std::size_t longest = 0;
  for (const Series& series : chart.series) longest = std::max(longest, series.name.size());
  const int total_width = std::max({width, static_cast<int>(right + 46 + 7.0 * longest + 10),
                                    static_cast<int>(8.0 * chart.title.size() + 20)});
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << total_width << "\" height=\"" << height
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << "<text x=\"" << num(std::max((left + right) / 2, 4.0 * chart.title.size() + 10))
     << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
     << escape(chart.title) << "</text>\n";
  // Grid lines at every tick; a label where it does not crowd the last one (40 px
  // apart along x, 16 along y).
  double last = -1e9;
  for (double t : axis_ticks(ax.lo, ax.hi, ax.log)) {
    if (t < ax.lo * (1 - 1e-9) - 1e-12 || t > ax.hi * (1 + 1e-9) + 1e-12) continue;
    const double x = ax.map(t, left, right);
    os << "<line x1=\"" << num(x) << "\" y1=\"" << num(top) << "\" x2=\"" << num(x) << "\" y2=\"" << num(bottom)
       << "\" stroke=\"#ddd\"/>\n";
    if (x - last < 40) continue;
    last = x;
    os << "<text x=\"" << num(x) << "\" y=\"" << num(bottom + 16) << "\" text-anchor=\"middle\">"
       << tick_label(t, ax.log) << "</text>\n";
  }
  last = 1e9;
  for (double t : axis_ticks(ay.lo, ay.hi, ay.log)) {
    if (t < ay.lo * (1 - 1e-9) - 1e-12 || t > ay.hi * (1 + 1e-9) + 1e-12) continue;
    const double y = ay.map(t, bottom, top);
    os << "<line x1=\"" << num(left) << "\" y1=\"" << num(y) << "\" x2=\"" << num(right) << "\" y2=\"" << num(y)
       << "\" stroke=\"#ddd\"/>\n";
    if (last - y < 16) continue;
    last = y;
    os << "<text x=\"" << num(left - 6) << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\">"
       << tick_label(t, ay.log) << "</text>\n";
  }
  os << "<rect x=\"" << num(left) << "\" y=\"" << num(top) << "\" width=\"" << num(right - left) << "\" height=\""
     << num(bottom - top) << "\" fill=\"none\" stroke=\"black\"/>\n"
     << "<text x=\"" << num((left + right) / 2) << "\" y=\"" << num(bottom + 40) << "\" text-anchor=\"middle\">"
     << escape(chart.x_label) << "</text>\n"
     << "<text transform=\"translate(20," << num((top + bottom) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
     << escape(chart.y_label) << "</text>\n";
  // Series, each with its colour and marker shape, and its legend entry.
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const Series& series = chart.series[s];
    const std::string colour = palette[s % std::size(palette)];
    std::string points;
    std::ostringstream marks;
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
      if (!usable(series.x[i], ax.log) || !usable(series.y[i], ay.log)) continue;
      const double x = ax.map(series.x[i], left, right), y = ay.map(series.y[i], bottom, top);
      points += num(x) + "," + num(y) + " ";
      if (series.mark != Mark::Line) {
        if (s % 3 == 0) marks << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3.5\"";
        else if (s % 3 == 1) marks << "<rect x=\"" << num(x - 3.5) << "\" y=\"" << num(y - 3.5) << "\" width=\"7\" height=\"7\"";
        else marks << "<path d=\"M" << num(x) << "," << num(y - 4.5) << " l4,7.5 h-8 z\"";
        marks << " fill=\"" << colour << "\"/>\n";
      }
    }
    if (series.mark != Mark::Points && !points.empty())
      os << "<polyline points=\"" << points << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
    os << marks.str();
    const double ly = top + 10 + 20.0 * s;
    os << "<line x1=\"" << num(right + 15) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(right + 40) << "\" y2=\""
       << num(ly) << "\" stroke=\"" << colour << "\" stroke-width=\"3\"/>\n<text x=\"" << num(right + 46)
       << "\" y=\"" << num(ly + 4) << "\">" << escape(series.name) << "</text>\n";
  }
  os << "</svg>\n";
  return os.str();
}

void write_svg(const Chart& chart, const std::filesystem::path& file, int width, int height) {
  write_atomically(file, [&](std::ostream& out) { out << to_svg(chart, width, height); });
}

}  // namespace gi
