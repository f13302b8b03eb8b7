#pragma once
#include <string>
#include <vector>

#include "gi/image/image.hpp"

namespace gi {

// A matrix as a labelled heat map: its picture (one pixel per entry, row i at y = i,
// e.g. false_colour of log10 F_ij) scaled up, each group of rows named on the left and
// each group of columns above, with what rows and columns are ("from", "to"). Lesson
// 07's form factors, element by element and object by object.
struct MatrixChart {
  std::string title;
  Image picture;                    // square: n x n entries
  std::vector<std::string> groups;  // the groups' names, in order
  std::vector<int> starts;          // the first row (and column) of each group: 0, then increasing
  std::string row_label = "from", column_label = "to";
  // Optional, for a small matrix: each entry's value as text, row by row, written in its cell.
  std::vector<std::string> cells;
};

// SVG text and its size in pixels, the matrix `side` pixels square, its picture
// embedded (a PNG data URL), so the file stands alone. Throws std::invalid_argument for
// a picture that is not square, groups and starts of different lengths or starts out
// of order, or a wrong number of cells.
struct MatrixSvg {
  std::string text;
  int width = 0, height = 0;
};
MatrixSvg matrix_svg(const MatrixChart& chart, int side = 440);

}  // namespace gi
