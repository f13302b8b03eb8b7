// Graded tests of exercise 7.3: projecting a direction onto the hemicube. One point
// per test.
#include <gtest/gtest.h>

#include "gi/radiosity/form_factors/hemicube.hpp"
#include "support/print.hpp"

using gi::HemicubeFace;
using gi::vec3;

namespace {
void expect_cell(const vec3& d, int res, HemicubeFace face, int column, int row, const char* why) {
  const auto cell = gi::project_to_hemicube(d, res);
  ASSERT_TRUE(cell.has_value()) << why;
  EXPECT_EQ(cell->face, face) << why;
  EXPECT_EQ(cell->column, column) << why;
  EXPECT_EQ(cell->row, row) << why;
}
}  // namespace

TEST(Ex7_3_Projection, StraightUpIsTheTopCentre) {
  expect_cell({0, 0, 1}, 100, HemicubeFace::Top, 50, 50, "(0, 0, 1) meets the top face at its centre");
}

TEST(Ex7_3_Projection, BelowTheHorizonIsNothing) {
  EXPECT_FALSE(gi::project_to_hemicube({0.3, 0.2, -0.5}, 100)) << "z < 0 is behind the patch";
  EXPECT_FALSE(gi::project_to_hemicube({1, 0, 0}, 100)) << "z = 0 lies in the patch's plane: no cell";
}

TEST(Ex7_3_Projection, EachSideFace) {
  const std::pair<vec3, HemicubeFace> cases[] = {{{1, 0.2, 0.5}, HemicubeFace::PlusX},
                                                 {{-1, 0.2, 0.5}, HemicubeFace::MinusX},
                                                 {{0.1, 1, 0.3}, HemicubeFace::PlusY},
                                                 {{0.1, -1, 0.3}, HemicubeFace::MinusY}};
  for (const auto& [d, face] : cases) {
    const auto cell = gi::project_to_hemicube(d, 10);
    ASSERT_TRUE(cell.has_value()) << "every direction with z > 0 meets the hemicube";
    EXPECT_EQ(cell->face, face) << "direction " << testing::PrintToString(d)
                                << ": the face is the axis with the largest |component|, with its sign";
  }
}

TEST(Ex7_3_Projection, TopCellIndices) {
  // (x, y) / z = (0.5, -0.25): column (0.5 + 1) / 2 * 8 = 6, row (-0.25 + 1) / 2 * 8 = 3.
  expect_cell({1, -0.5, 2}, 8, HemicubeFace::Top, 6, 3, "divide by z to reach the plane z = 1, then map [-1, 1] to cells");
}

TEST(Ex7_3_Projection, SideCellIndices) {
  // On the face x = 1: (y, z) / x = (-0.5, 0.5): column 25 of 100, row 25 of 50. Every
  // coordinate falls on a cell's edge, so rounding and truncating agree here.
  const auto cell = gi::project_to_hemicube({2, -1, 1}, 100);
  ASSERT_TRUE(cell.has_value()) << "every direction with z > 0 meets the hemicube";
  EXPECT_EQ(cell->face, HemicubeFace::PlusX) << "direction (2, -1, 1): the face is the axis with the largest "
                                                "|component|, with its sign";
  EXPECT_EQ(cell->column, 25)
      << "on the face x = 1 the column runs along y, from y = -1 (column 0) to y = 1: y / |x| = -0.5 lies in column 25"
      << (cell->column == 75 ? "; yours is column 75, the mirror image: u = y / |x|, with the sign of y" : "");
  EXPECT_EQ(cell->row, 25) << "divide by |x| to reach the face x = 1; rows count up from the horizon z = 0 over "
                              "[0, 1]: z / |x| = 0.5 lies in row 25 of 50";
}

TEST(Ex7_3_Projection, CellsAreCountedNotRounded) {
  // Top: (x, y) / z = (0.3, -0.55): column (0.3 + 1) / 2 * 10 = 6.5, row 2.25.
  expect_cell({0.3, -0.55, 1}, 10, HemicubeFace::Top, 6, 2,
              "a point 6.5 cells from the edge lies in cell 6: truncate towards the edge, do not round");
  // On x = 1: (y, z) / x = (-0.45, 0.35): column 2.75, row 1.75.
  expect_cell({2, -0.9, 0.7}, 10, HemicubeFace::PlusX, 2, 1,
              "a point 2.75 cells across lies in cell 2: truncate towards the edge, do not round");
}

TEST(Ex7_3_Projection, CellsOnTheMinusFaces) {
  // On the face x = -1: (y, z) / |x| = (0.5, 0.5): column 75 of 100, row 25 of 50.
  expect_cell({-2, 1, 1}, 100, HemicubeFace::MinusX, 75, 25,
              "divide by |x|, not x, to reach the face x = -1: the height z / |x| is positive on every side face");
  // On the face y = -1: (x, z) / |y| = (-0.5, 0.25): column 25 of 100, row 12 of 50.
  expect_cell({-2, -4, 1}, 100, HemicubeFace::MinusY, 25, 12,
              "divide by |y|, not y, to reach the face y = -1; columns run along x counted from -1");
}

TEST(Ex7_3_Projection, LengthDoesNotMatter) {
  const auto a = gi::project_to_hemicube({0.3, 0.1, 0.2}, 50), b = gi::project_to_hemicube({3, 1, 2}, 50);
  ASSERT_TRUE(a && b) << "both directions have z > 0 and meet the hemicube";
  EXPECT_EQ(a->face, b->face) << "a direction need not be unit length: only ratios matter";
  EXPECT_EQ(a->column, b->column) << "a direction need not be unit length: only ratios matter";
  EXPECT_EQ(a->row, b->row) << "a direction need not be unit length: only ratios matter";
}

TEST(Ex7_3_Projection, EdgesStayInsideTheGrid) {
  for (const vec3& d : {vec3(1, 1, 1), vec3(-1, -1, 1), vec3(1, -1, 1e-9), vec3(-1, 1, 1)}) {
    const auto cell = gi::project_to_hemicube(d, 10);
    ASSERT_TRUE(cell.has_value()) << "every direction with z > 0 meets the hemicube";
    const int rows = cell->face == HemicubeFace::Top ? 10 : 5;
    EXPECT_GE(cell->column, 0) << "a direction through a cube edge must land in a valid cell: clamp";
    EXPECT_LT(cell->column, 10) << "a direction through a cube edge must land in a valid cell: clamp";
    EXPECT_GE(cell->row, 0) << "a direction through a cube edge must land in a valid cell: clamp";
    EXPECT_LT(cell->row, rows) << "side faces have res/2 rows; clamp";
  }
}
