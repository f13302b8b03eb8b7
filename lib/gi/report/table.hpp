#pragma once
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>
#include <variant>
#include <vector>

namespace gi {

// How a column prints its numbers: Auto is fixed-point, switching to scientific
// for very small or very large magnitudes.
enum class Format { Auto, Fixed, Scientific };

struct Column {
  std::string name;
  int precision = 3;
  Format format = Format::Auto;
};

// One table cell: an integer, a real number or text.
struct Cell {
  std::variant<long long, double, std::string> value;
  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  Cell(Int v) : value(static_cast<long long>(v)) {}
  Cell(double v) : value(v) {}
  Cell(const char* v) : value(std::string(v)) {}
  Cell(std::string v) : value(std::move(v)) {}
};

// A table as it prints, cell by cell, for pages that lay it out themselves (HTML).
// A column holding any number is numeric: its cells align right.
struct TableText {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;
};

// The lessons' tables: printed aligned to stdout, and written as CSV for plotting.
class Table {
 public:
  Table(std::string title, std::vector<Column> columns);
  // Throws std::invalid_argument on a wrong cell count, std::runtime_error on a NaN or an
  // infinite number (a value that does not exist is a text cell such as "-").
  void add_row(std::vector<Cell> cells);
  void print(std::ostream& os = std::cout) const;
  std::string to_string() const;
  TableText text() const;
  const std::string& title() const { return title_; }
  // Creates parent folders; atomic (gi/core/atomic_file.hpp); throws WriteError.
  void write_csv(const std::filesystem::path& file) const;
  std::size_t rows() const { return rows_.size(); }

 private:
  std::string title_;
  std::vector<Column> columns_;
  std::vector<std::vector<Cell>> rows_;
};

// A number as a table prints it.
std::string format_number(double value, int precision, Format format);

}  // namespace gi
