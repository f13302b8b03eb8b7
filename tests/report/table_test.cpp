#include "gi/report/table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

TEST(Table, AlignsTextLeftAndNumbersRight) {
  gi::Table table("Title", {{"name"}, {"n"}, {"x", 2}});
  table.add_row({"a", 5, 1.5});
  table.add_row({"long name", 12345, 0.25});
  EXPECT_EQ(table.to_string(),
            "Title\n"
            "name           n     x\n"
            "----------------------\n"
            "a              5  1.50\n"
            "long name  12345  0.25\n");
}

TEST(Table, NumberFormats) {
  EXPECT_EQ(gi::format_number(0.000123, 2, gi::Format::Auto), "1.23e-04");
  EXPECT_EQ(gi::format_number(12345678.0, 1, gi::Format::Auto), "1.2e+07");
  EXPECT_EQ(gi::format_number(0.0, 3, gi::Format::Auto), "0.000");
  EXPECT_EQ(gi::format_number(3.14159, 2, gi::Format::Fixed), "3.14");
  EXPECT_EQ(gi::format_number(NAN, 2, gi::Format::Auto), "nan");
  EXPECT_EQ(gi::format_number(-INFINITY, 2, gi::Format::Auto), "-inf");
}

TEST(Table, WrongCellCountThrows) {
  gi::Table table("t", {{"a"}, {"b"}});
  EXPECT_THROW(table.add_row({1}), std::invalid_argument);
}

// A NaN in a table is a number gone wrong: the lesson stops rather than print it.
TEST(Table, ANumberThatIsNotFiniteIsRefused) {
  gi::Table table("errors", {{"shots"}, {"error"}});
  try {
    table.add_row({1, NAN});
    FAIL() << "a NaN was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "table 'errors', column 'error': the value is not a number (NaN); it cannot be shown");
  }
  EXPECT_THROW(table.add_row({2, -INFINITY}), std::runtime_error);
  table.add_row({3, "-"});  // a value that does not exist
  EXPECT_EQ(table.rows(), 1u);
}

TEST(Table, CsvQuotesAndKeepsFullPrecision) {
  gi::Table table("t", {{"label"}, {"value"}});
  table.add_row({"a, \"quoted\" b", 0.1 + 0.2});
  const auto file = std::filesystem::path(testing::TempDir()) / "gi_table_test" / "t.csv";
  table.write_csv(file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "label,value\n\"a, \"\"quoted\"\" b\",0.30000000000000004\n");
}
