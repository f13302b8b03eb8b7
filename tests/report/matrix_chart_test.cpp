#include "gi/report/matrix_chart.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace {

// The 3 x 3 matrix of two groups, "walls" (rows 0 and 1) and "light" (row 2).
gi::MatrixChart small() {
  gi::MatrixChart chart;
  chart.title = "F between <objects>";
  chart.picture = gi::Image(3, 3, gi::Pixel(0.5f));
  chart.groups = {"walls", "light"};
  chart.starts = {0, 2};
  return chart;
}

int count(const std::string& text, const std::string& word) {
  int n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(MatrixChart, NamesEachGroupBesideItsRowsAndAboveItsColumns) {
  const gi::MatrixSvg svg = gi::matrix_svg(small(), 300);
  EXPECT_EQ(count(svg.text, ">walls</text>"), 2);
  EXPECT_EQ(count(svg.text, ">light</text>"), 2);
  EXPECT_NE(svg.text.find("from (rows)"), std::string::npos);
  EXPECT_NE(svg.text.find("to (columns)"), std::string::npos);
  EXPECT_NE(svg.text.find("F between &lt;objects&gt;"), std::string::npos) << "the title is escaped";
  // The picture is inside, as a PNG: base64 of its 8-byte signature starts so.
  EXPECT_NE(svg.text.find("href=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);
  EXPECT_GT(svg.width, 300);
  EXPECT_GT(svg.height, 300);
  // Rows 0-1 and row 2 of 3 at 100 px a row: "walls" at the middle of rows 0 and 1.
  const std::size_t walls = svg.text.find(">walls</text>");
  const std::size_t y = svg.text.rfind("y=\"", walls);
  ASSERT_NE(y, std::string::npos);
  const double top = svg.height - 16 - 300;  // the matrix's top edge (16 px below it)
  EXPECT_NEAR(std::stod(svg.text.substr(y + 3)), top + 100 + 4, 1e-9);
}

TEST(MatrixChart, WritesEachCellsValueWhenGiven) {
  gi::MatrixChart chart = small();
  for (int k = 0; k < 9; ++k) chart.cells.push_back("c" + std::to_string(k));
  const std::string text = gi::matrix_svg(chart).text;
  for (int k = 0; k < 9; ++k) EXPECT_EQ(count(text, ">c" + std::to_string(k) + "</text>"), 1);
}

TEST(MatrixChart, RefusesWhatItCannotDraw) {
  gi::MatrixChart not_square = small();
  not_square.picture = gi::Image(3, 2);
  EXPECT_THROW(gi::matrix_svg(not_square), std::invalid_argument);
  gi::MatrixChart unordered = small();
  unordered.starts = {0, 0};
  EXPECT_THROW(gi::matrix_svg(unordered), std::invalid_argument);
  gi::MatrixChart outside = small();
  outside.starts = {0, 3};
  EXPECT_THROW(gi::matrix_svg(outside), std::invalid_argument);
  gi::MatrixChart unmatched = small();
  unmatched.groups.pop_back();
  EXPECT_THROW(gi::matrix_svg(unmatched), std::invalid_argument);
  gi::MatrixChart few_cells = small();
  few_cells.cells = {"1"};
  EXPECT_THROW(gi::matrix_svg(few_cells), std::invalid_argument);
}
