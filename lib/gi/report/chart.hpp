#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace gi {

enum class Mark { Line, Points, LinePoints };

struct Series {
  std::string name;
  std::vector<double> x, y;
  Mark mark = Mark::LinePoints;
};

// A chart of one or more series, e.g. error against time for each method.
struct Chart {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<Series> series;
};

// SVG text of the chart: axes with 1-2-5 ticks (on log axes decades, or 1-2-5 and
// every digit of a decade when it spans fewer than four), labels, title and a legend. Points that are not finite, or not positive on a log axis,
// are left out.
std::string to_svg(const Chart& chart, int width = 720, int height = 480);
// Creates parent folders; atomic (gi/core/atomic_file.hpp); throws WriteError.
void write_svg(const Chart& chart, const std::filesystem::path& file, int width = 720, int height = 480);

// 10^e as the double nearest it, on every platform: 10^e is exact in a double for
// 0 <= e <= 22, and 1 / 10^-e is then rounded once, correctly. std::pow(10.0, e) need
// not be (MinGW's is a unit in the last place off at e = -3), and a tick at
// 0.0009999999999999998 is not the decade 10^-3 a reader sees.
double power_of_ten(int e);

// Tick positions covering [lo, hi]: 1-2-5 steps on a linear axis; on a log axis
// (lo > 0 there) powers of ten when four or more cover the range, else 1-2-5 x 10^k,
// else 1..9 x 10^k, else linear steps: never fewer than a few labels.
std::vector<double> axis_ticks(double lo, double hi, bool log);

}  // namespace gi
