#include "gi/report/matrix_chart.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "gi/core/base64.hpp"
#include "gi/image/image_io.hpp"
#include "gi/report/svg_canvas.hpp"

namespace gi {

namespace {

// Short names for the shared writers: the lines below are mostly numbers.
std::string num(double v) { return svg_number(v); }
std::string escape(const std::string& s) { return svg_escape(s); }

}  // namespace


MatrixSvg matrix_svg(const MatrixChart& chart, int side) {
  const int n = chart.picture.width;
  if (n < 1 || chart.picture.height != n) throw std::invalid_argument("matrix chart: the picture must be square");
  if (chart.groups.size() != chart.starts.size() || chart.starts.empty() || chart.starts[0] != 0)
    throw std::invalid_argument("matrix chart: one start per group, the first 0");
  for (std::size_t g = 1; g < chart.starts.size(); ++g)
    if (chart.starts[g] <= chart.starts[g - 1] || chart.starts[g] >= n)
      throw std::invalid_argument("matrix chart: the groups' starts must increase within the matrix");
  if (!chart.cells.empty() && chart.cells.size() != static_cast<std::size_t>(n) * n)
    throw std::invalid_argument("matrix chart: one cell text per entry, or none");

  // Margins for the longest name (about 7 px a character at font size 12).
  std::size_t longest = std::max(chart.row_label.size(), chart.column_label.size());
  for (const std::string& g : chart.groups) longest = std::max(longest, g.size());
  const int label = 7 * static_cast<int>(longest) + 14, left = label + 22, top = label + 44;
  const int width = left + side + 16, height = top + side + 16;
  const double cell = static_cast<double>(side) / n;
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
     << num(height)
     << "\" viewBox=\"0 0 " << num(width) << ' ' << num(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << "<text x=\"" << num(width / 2.0) << "\" y=\"20\" text-anchor=\"middle\" font-size=\"15\">"
     << escape(chart.title)
     << "</text>\n"
     << "<image x=\"" << num(left) << "\" y=\"" << num(top) << "\" width=\"" << side << "\" height=\"" << side
     << "\" preserveAspectRatio=\"none\" style=\"image-rendering: pixelated\" href=\"data:image/png;base64,"
     << base64(encode_png(chart.picture)) << "\"/>\n";
  // Each group named at the middle of its rows (left) and of its columns (above, upwards).
  for (std::size_t g = 0; g < chart.groups.size(); ++g) {
    const int first = chart.starts[g], end = g + 1 < chart.starts.size() ? chart.starts[g + 1] : n;
    const double middle = 0.5 * (first + end) * cell;
    os << "<text x=\"" << num(left - 6) << "\" y=\"" << num(top + middle + 4) << "\" text-anchor=\"end\">"
       << escape(chart.groups[g]) << "</text>\n"
       << "<text transform=\"translate(" << num(left + middle + 4) << ',' << num(top - 6)
       << ") rotate(-90)\" text-anchor=\"start\">" << escape(chart.groups[g]) << "</text>\n";
    if (g > 0)  // ticks at the borders, outside the picture
      os << "<line x1=\"" << num(left - 4) << "\" x2=\"" << num(left) << "\" y1=\"" << num(top + first * cell)
         << "\" y2=\"" << num(top + first * cell) << "\" stroke=\"black\"/>\n"
         << "<line y1=\"" << num(top - 4) << "\" y2=\"" << num(top) << "\" x1=\"" << num(left + first * cell)
         << "\" x2=\"" << num(left + first * cell) << "\" stroke=\"black\"/>\n";
  }
  // What the rows and the columns are.
  os << "<text transform=\"translate(14," << num(top + side / 2.0) << ") rotate(-90)\" text-anchor=\"middle\" "
     << "font-weight=\"bold\">" << escape(chart.row_label) << " (rows)</text>\n"
     << "<text x=\"" << num(left + side / 2.0) << "\" y=\"40\" text-anchor=\"middle\" font-weight=\"bold\">"
     << escape(chart.column_label) << " (columns)</text>\n";
  // A small matrix's values in its cells, dark on the ramp's bright end, white elsewhere.
  for (std::size_t k = 0; k < chart.cells.size(); ++k) {
    const int i = static_cast<int>(k) / n, j = static_cast<int>(k) % n;
    const Pixel& p = chart.picture.at(j, i);
    const bool bright = 0.3 * p.x + 0.59 * p.y + 0.11 * p.z > 0.45;
    os << "<text x=\"" << num(left + (j + 0.5) * cell) << "\" y=\"" << num(top + (i + 0.5) * cell + 4)
       << "\" text-anchor=\"middle\" fill=\"" << (bright ? "black" : "white") << "\">" << escape(chart.cells[k])
       << "</text>\n";
  }
  os << "</svg>\n";
  return {os.str(), width, height};
}

}  // namespace gi
